"""What both Processing algorithms share: each runs a tool of the plugin, shows
the plugin's icon, and has a help page (help/<name>.html) shown in the
dialog's panel and behind its Help button."""

import os

from qgis.core import QgsApplication, QgsProcessingAlgorithm, QgsProcessingException
from qgis.PyQt.QtCore import QCoreApplication, QUrl
from qgis.PyQt.QtGui import QIcon

ICON = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'icon.svg')


def file_of(layer, what):
    """The file behind a layer (the tools read files), or QgsProcessingException."""
    path = layer.source().split('|')[0]
    if not os.path.isfile(path):
        raise QgsProcessingException(f'The {what} layer must be a file (its source is "{layer.source()}"); '
                                     'save it to a file first.')
    return path


class Progress:
    """feedback.setProgress, remembering whether a progress bar is open (begun, not at 100)."""

    def __init__(self, feedback):
        self.feedback = feedback
        self.percent = None

    def __call__(self, percent):
        self.percent = percent
        self.feedback.setProgress(percent)

    def open(self):
        return self.percent is not None and self.percent < 100


def failure(message, feedback, progress):
    """The QgsProcessingException that ends a failed run, `message` its one line.

    qgis_process draws the progress bar on stdout without ending its line until
    100: a bar cut short is ended here, or what follows runs on after it. And it
    prints an algorithm's error three times on stderr: QGIS logs it as Critical
    (which qgis_process echoes), its console feedback prints "ERROR:" and logs it
    again. The log is silenced there (the run, and qgis_process, end with this
    error), leaving the "ERROR:" line. The QGIS application shows each once.
    """
    if QgsApplication.platform() == 'qgis_process':
        if progress.open():
            feedback.pushConsoleInfo('')
        QgsApplication.messageLog().blockSignals(True)
    return QgsProcessingException(message)


class ToolAlgorithm(QgsProcessingAlgorithm):
    SHORT_HELP = ''  # the help panel's first sentences
    HELP_FILE = ''   # tool.help_file(name)
    HELP = ''        # tool.read_help(HELP_FILE)
    RENAMED = {}     # a name of an earlier version -> the parameter that replaced it
    RENAMED_AS = ''  # whose names the new ones are, for the hint ("as gdal:fillnodata")

    def tr(self, string):
        return QCoreApplication.translate(type(self).__name__, string)

    def checkParameterValues(self, parameters, context):  # noqa: N802
        ok, message = super().checkParameterValues(parameters, context)
        if not ok:
            return ok, message
        # qgis_process and scripts pass names QGIS would otherwise drop silently.
        known = {p.name() for p in self.parameterDefinitions()}
        for name in parameters:
            if name in known:
                continue
            hint = self.RENAMED.get(name)
            if hint:
                return False, self.tr('Unknown parameter {} (use {}, {})').format(name, hint, self.RENAMED_AS)
            return False, self.tr('Unknown parameter {} (known: {})').format(name, ', '.join(sorted(known)))
        return True, ''

    def icon(self):
        return QIcon(ICON)

    def svgIconPath(self):  # noqa: N802
        return ICON

    def shortHelpString(self):  # noqa: N802
        # The whole help, as plain lines (tool.read_help): QGIS 3.22 shows only this
        # one, in the dialog's panel and in qgis_process help (helpString() nowhere).
        return self.tr(self.SHORT_HELP) + '\n' + self.tr(self.HELP)

    def helpString(self):  # noqa: N802
        return self.tr(self.HELP)

    def helpUrl(self):  # noqa: N802
        # The help page shipped with the plugin: the dialog's Help button opens it.
        return QUrl.fromLocalFile(self.HELP_FILE).toString()

    def flags(self):
        # The tool runs in its own process; nothing here touches the GUI or layers.
        return super().flags() | QgsProcessingAlgorithm.FlagDisplayNameIsLiteral
