"""The `mcmd:terrain` Processing algorithm: runs the mcmd_terrain CLI.

Makes a terrain (a DEM) from scratch, around a sketch layer, around ridge and
river line layers, or around a generated skeleton of ridges and rivers; the
result is loaded as a layer. The command line is the tool's (docs/terrain.md).
"""

import os
import shlex
import shutil
import sys

from qgis.core import (Qgis,
                       QgsMessageLog,
                       QgsProcessing,
                       QgsProcessingException,
                       QgsProcessingParameterCrs,
                       QgsProcessingParameterDefinition,
                       QgsProcessingParameterEnum,
                       QgsProcessingParameterExtent,
                       QgsProcessingParameterFileDestination,
                       QgsProcessingParameterNumber,
                       QgsProcessingParameterRasterDestination,
                       QgsProcessingParameterRasterLayer,
                       QgsProcessingParameterString,
                       QgsProcessingParameterVectorLayer,
                       QgsRasterFileWriter)

from . import tool
from .tool_algorithm import Progress, ToolAlgorithm, failure, file_of

TERRAIN_TOOL = 'mcmd_terrain'

# (CLI arguments, label); the first is the tool's default.
METHODS = [
    ([], 'MCMD (thin plate + fractal relief, creased ridges and rivers; default)'),
    (['-method', 'paper-ds'], 'Paper, diamond-square'),
    (['-method', 'paper-te'], 'Paper, triangle-edge'),
    (['-method', 'paper', '-scheme', 'butterfly'], 'Paper, butterfly stencil'),
    (['-method', 'mdi', '-scheme', 'te'], 'MDI (Belhadj & Audibert 2005), triangle-edge'),
]
GENERATORS = [
    ([], 'None: the sketch, lines and extent only'),
    (['-skeleton'], 'Ridges-and-rivers skeleton'),
    (['-peaks', 'iizuka'], "Iizuka's peaks (Table 1)"),
]

_DOUBLE = QgsProcessingParameterNumber.Double
_INT = QgsProcessingParameterNumber.Integer
# name, flag, label, type, default (not passed when equal), min, max, advanced
NUMBERS = [
    ('H', '-H', 'Roughness exponent H (high = rolling, low = rugged)', _DOUBLE, 0.7, 0.0, 1.0, False),
    ('SEED', '-seed', 'Random seed', _INT, 0, 0, None, False),
    ('SHARPNESS', '-sharpness', 'Sharpness of ridges and rivers (MCMD method)', _DOUBLE, 1.0, 0.0, 10.0,
     True),
    ('RT', '-rt', 'Bias rt (> 0 raises, < 0 lowers the terrain between constraints)', _DOUBLE, 0.0,
     -1.0, 1.0, True),
    ('I', '-I', 'Paper methods: top-down shape I', _DOUBLE, 0.0, -100.0, 100.0, True),
    ('I_BU', '-Ibu', 'Paper methods: bottom-up shape I_bu', _DOUBLE, 0.0, -100.0, 100.0, True),
    ('UPSAMPLE', '-upsample', 'Supersample the sketch by this factor (1 = no)', _INT, 1, 1, 1024, True),
    ('MEDIAN', '-median', 'Median filter size after the synthesis (0 = none, odd)', _INT, 0, 0, 101, True),
    ('DIFFUSION', '-diffusion', 'Erosion: hillslope diffusion, a factor of the default (0 = none)', _DOUBLE, 1.0,
     0.0, 100.0, True),
    ('TALUS', '-talus', 'Erosion: talus angle in degrees (90 = none)', _DOUBLE, 90.0, 0.1, 90.0, True),
]
# name, flag, label, advanced
STRINGS = [
    ('RIDGE_Z', '-ridge-z', 'Height of ridge line cells without one (Z or Z1,Z2)', False),
    ('RIVER_Z', '-river-z', 'Height of river line cells without one (Z1,Z2: source, mouth)', False),
    ('ZRANGE', '-zrange', 'Elevations of the grey levels or generator, "MIN MAX"', False),
    ('UNKNOWN', '-unknown', 'Sketch cells to synthesise (white, black, none or a value)', True),
    ('EROSION', '-erode', 'Erosion: auto, steps on the finest grid, or 0 (empty: on for a skeleton, '
     'from scratch or around lines, off for a sketch)', False),
    ('EROSION_LAW', '-erosion', 'Erosion: stream-power law K,m,n (K a number or auto)', True),
    ('UPLIFT', '-uplift', 'Erosion: uplift, terrain, uniform or a raster file', True),
]


def find_terrain_executable():
    """mcmd_terrain beside the configured mcmd_fillnodata, else on PATH; ToolError if neither."""
    name = TERRAIN_TOOL + ('.exe' if sys.platform == 'win32' else '')
    try:
        beside = os.path.join(os.path.dirname(tool.find_executable()), name)
        if os.path.isfile(beside) and os.access(beside, os.X_OK):
            return beside
    except tool.ToolError:
        pass
    on_path = shutil.which(TERRAIN_TOOL)
    if on_path:
        return on_path
    raise tool.ToolError(f'{TERRAIN_TOOL} was not found beside mcmd_fillnodata nor on PATH; build it '
                         f'(build/bin/{TERRAIN_TOOL}) and put it next to the configured mcmd_fillnodata.')


class TerrainAlgorithm(ToolAlgorithm):
    SHORT_HELP = ('Makes a terrain from scratch, around a sketch, ridge and river lines or a generated '
                  'skeleton, by running the mcmd_terrain tool.')
    # The full help, an HTML page shipped in the plugin (also the help URL).
    HELP_FILE = tool.help_file('terrain')
    HELP = tool.read_help(HELP_FILE)
    RENAMED = {'CREATION_OPTIONS': 'OPTIONS'}
    RENAMED_AS = 'as mcmd:fillnodata and gdal:fillnodata'

    SKETCH = 'SKETCH'
    STATES = 'STATES'
    RIDGES = 'RIDGES'
    RIVERS = 'RIVERS'
    GENERATOR = 'GENERATOR'
    WIDTH = 'WIDTH'
    HEIGHT = 'HEIGHT'
    EXTENT = 'EXTENT'
    CRS = 'CRS'
    METHOD = 'METHOD'
    RS = 'RS'
    CREATION_OPTIONS = 'OPTIONS'
    EXTRA = 'EXTRA'
    HILLSHADE = 'HILLSHADE'
    OUTPUT = 'OUTPUT'

    def createInstance(self):  # noqa: N802
        return TerrainAlgorithm()

    def name(self):
        return 'terrain'

    def displayName(self):  # noqa: N802
        return self.tr('Make a terrain (MCMD)')

    def group(self):
        return self.tr('Raster creation')

    def groupId(self):  # noqa: N802
        return 'rastercreation'

    def tags(self):
        return self.tr('terrain,dem,sketch,ridge,river,skeleton,fractal,midpoint,synthesis,mcmd').split(',')

    def _add(self, param, advanced=False):
        if advanced:
            param.setFlags(param.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        self.addParameter(param)

    def initAlgorithm(self, config=None):  # noqa: N802
        self._add(QgsProcessingParameterRasterLayer(self.SKETCH, self.tr('Sketch'), optional=True))
        self._add(QgsProcessingParameterRasterLayer(self.STATES, self.tr('Ridge/river states of the sketch'),
                                                    optional=True), advanced=True)
        for name, label in ((self.RIDGES, 'Ridge lines'), (self.RIVERS, 'River lines')):
            self._add(QgsProcessingParameterVectorLayer(name, self.tr(label), [QgsProcessing.TypeVectorLine],
                                                        optional=True))
        self._add(QgsProcessingParameterEnum(self.GENERATOR, self.tr('Generator'),
                                             options=[self.tr(label) for _, label in GENERATORS],
                                             defaultValue=0))
        for name, label in ((self.WIDTH, 'Width (cells, without a sketch)'),
                            (self.HEIGHT, 'Height (cells, without a sketch)')):
            size = QgsProcessingParameterNumber(name, self.tr(label), type=_INT, defaultValue=513)
            size.setMinimum(1)
            self._add(size)
        self._add(QgsProcessingParameterExtent(self.EXTENT, self.tr('Extent (without a sketch)'), optional=True))
        self._add(QgsProcessingParameterCrs(self.CRS, self.tr('CRS (without a sketch)'), optional=True))
        self._add(QgsProcessingParameterEnum(self.METHOD, self.tr('Method'),
                                             options=[self.tr(label) for _, label in METHODS],
                                             defaultValue=0))
        self._add(QgsProcessingParameterString(
            self.RS, self.tr('Roughness RS (a fraction of the range, e.g. 300m, or auto)'), defaultValue='0'))
        for name, _flag, label, kind, default, minimum, maximum, advanced in NUMBERS:
            number = QgsProcessingParameterNumber(name, self.tr(label), type=kind, defaultValue=default)
            if minimum is not None:
                number.setMinimum(minimum)
            if maximum is not None:
                number.setMaximum(maximum)
            self._add(number, advanced)
        for name, _flag, label, advanced in STRINGS:
            self._add(QgsProcessingParameterString(name, self.tr(label), optional=True), advanced)
        options = QgsProcessingParameterString(self.CREATION_OPTIONS, self.tr('Creation options'),
                                               defaultValue='', optional=True)
        options.setMetadata({'widget_wrapper': {
            'class': 'processing.algs.gdal.ui.RasterOptionsWidget.RasterOptionsWidgetWrapper'}})
        self._add(options, advanced=True)
        self._add(QgsProcessingParameterString(self.EXTRA, self.tr('Additional command-line parameters'),
                                               optional=True), advanced=True)
        self._add(QgsProcessingParameterFileDestination(self.HILLSHADE, self.tr('Hillshade preview'),
                                                        'PNG files (*.png)', optional=True,
                                                        createByDefault=False))
        self._add(QgsProcessingParameterRasterDestination(self.OUTPUT, self.tr('Terrain')))

    # ---- command line -----------------------------------------------------

    def _georeferencing(self, parameters, context):
        """-size, -a_ullr, -a_srs for a terrain made without a sketch."""
        args = ['-size', str(self.parameterAsInt(parameters, self.WIDTH, context)),
                str(self.parameterAsInt(parameters, self.HEIGHT, context))]
        crs = self.parameterAsCrs(parameters, self.CRS, context)
        if parameters.get(self.EXTENT):
            box = self.parameterAsExtent(parameters, self.EXTENT, context, crs)
            if not crs.isValid():
                crs = self.parameterAsExtentCrs(parameters, self.EXTENT, context)
            args += ['-a_ullr'] + [repr(v) for v in (box.xMinimum(), box.yMaximum(), box.xMaximum(),
                                                     box.yMinimum())]
        if crs.isValid():
            args += ['-a_srs', crs.authid() or crs.toWkt()]
        return args

    def _inputs(self, parameters, context):
        """The sketch (or georeferencing), states and line layers."""
        args, sketch = [], None
        layer = self.parameterAsRasterLayer(parameters, self.SKETCH, context)
        if layer is not None:
            sketch = file_of(layer, 'sketch')
        else:
            args += self._georeferencing(parameters, context)
        states = self.parameterAsRasterLayer(parameters, self.STATES, context)
        if states is not None:
            args += ['-states', file_of(states, 'states')]
        for name, flag, what in ((self.RIDGES, '-ridges', 'ridge'), (self.RIVERS, '-rivers', 'river')):
            lines = self.parameterAsVectorLayer(parameters, name, context)
            if lines is not None:
                args += [flag, file_of(lines, what + ' lines')]
        args += GENERATORS[self.parameterAsEnum(parameters, self.GENERATOR, context)][0]
        return args, sketch

    def _settings(self, parameters, context):
        """Method, roughness and the other numbers and strings, when not the tool's defaults."""
        args = list(METHODS[self.parameterAsEnum(parameters, self.METHOD, context)][0])
        rs = (self.parameterAsString(parameters, self.RS, context) or '0').strip()
        if rs not in ('0', '0m'):
            args += ['-rs', rs]
        for name, flag, _label, kind, default, _min, _max, _adv in NUMBERS:
            value = (self.parameterAsInt if kind == _INT else self.parameterAsDouble)(parameters, name, context)
            if value != default:
                args += [flag, str(value)]
        for name, flag, _label, _adv in STRINGS:
            text = (self.parameterAsString(parameters, name, context) or '').strip()
            if text:
                args += [flag] + (text.replace(',', ' ').split() if flag == '-zrange' else [text])
        return args

    def build_command(self, parameters, context, executable):
        """The argument list and the output path."""
        inputs, sketch = self._inputs(parameters, context)
        output = self.parameterAsOutputLayer(parameters, self.OUTPUT, context)
        if not output:
            raise QgsProcessingException(self.tr('No output file given.'))
        args = [executable] + inputs + self._settings(parameters, context)
        driver = QgsRasterFileWriter.driverForExtension(os.path.splitext(output)[1]) or 'GTiff'
        args += ['-of', driver]
        for option in (self.parameterAsString(parameters, self.CREATION_OPTIONS, context) or '').split('|'):
            if option.strip():
                args += ['-co', option.strip()]
        hillshade = self.parameterAsFileOutput(parameters, self.HILLSHADE, context)
        if hillshade:
            args += ['-hillshade', hillshade]
        extra = self.parameterAsString(parameters, self.EXTRA, context)
        if extra and extra.strip():
            args += shlex.split(extra)
        return args + ([sketch] if sketch else []) + [output], output, hillshade

    # ---- run --------------------------------------------------------------

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        try:
            executable = find_terrain_executable()
        except tool.ToolError as err:
            raise QgsProcessingException(str(err)) from err
        args, output, hillshade = self.build_command(parameters, context, executable)
        command = tool.command_string(args)
        QgsMessageLog.logMessage(command, 'Processing', Qgis.Info)
        feedback.pushInfo(self.tr('mcmd_terrain command:'))
        feedback.pushCommandInfo(command)
        folder = os.path.dirname(os.path.abspath(output))
        os.makedirs(folder, exist_ok=True)
        existing = tool.snapshot(folder)
        shade_existing = tool.snapshot(os.path.dirname(os.path.abspath(hillshade))) if hillshade else None
        progress = Progress(feedback)
        try:
            for line in tool.run(args, on_progress=progress, on_info=feedback.pushConsoleInfo,
                                 is_canceled=feedback.isCanceled, tool_name=TERRAIN_TOOL):
                feedback.pushWarning(line)
        except tool.ToolError as err:
            for path in tool.remove_outputs(output, existing) + (
                    tool.remove_outputs(hillshade, shade_existing) if hillshade else []):
                feedback.pushInfo(self.tr('Removed {}').format(path))
            raise failure(str(err), feedback, progress) from err
        if not os.path.exists(output):
            raise QgsProcessingException(self.tr('mcmd_terrain wrote no output at {}').format(output))
        feedback.setProgress(100)
        return {self.OUTPUT: output, self.HILLSHADE: hillshade or None}
