"""The `mcmd` Processing provider ("MCMD void fill")."""

import os

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtGui import QIcon

from . import tool
from .fillnodata import FillNodataAlgorithm
from .terrain import TerrainAlgorithm

try:  # the Processing plugin ships with QGIS; guard anyway so the provider still loads
    from processing.core.ProcessingConfig import ProcessingConfig, Setting
except ImportError:  # pragma: no cover
    ProcessingConfig = None
    Setting = None

PLUGIN_DIR = os.path.dirname(os.path.abspath(__file__))


class McmdProvider(QgsProcessingProvider):
    """Holds the mcmd algorithms and the provider's settings."""

    def id(self):
        return 'mcmd'

    def name(self):
        return 'MCMD void fill'

    def longName(self):  # noqa: N802
        version = tool.plugin_version()
        return f'MCMD void fill ({version})' if version else self.name()

    def icon(self):
        return QIcon(os.path.join(PLUGIN_DIR, 'icon.svg'))

    def svgIconPath(self):  # noqa: N802
        return os.path.join(PLUGIN_DIR, 'icon.svg')

    def load(self):
        # Shown under Settings > Options > Processing > Providers > MCMD void fill.
        if ProcessingConfig is not None:
            ProcessingConfig.setGroupIcon(self.name(), self.icon())
            ProcessingConfig.addSetting(Setting(
                self.name(), tool.SETTING_EXECUTABLE,
                self.tr('mcmd_fillnodata executable (empty: bin/ next to the plugin, then PATH)'),
                '', valuetype=Setting.FILE))
            ProcessingConfig.readSettings()
        self.refreshAlgorithms()
        return True

    def unload(self):
        if ProcessingConfig is not None and tool.SETTING_EXECUTABLE in ProcessingConfig.settings:
            ProcessingConfig.removeSetting(tool.SETTING_EXECUTABLE)

    def loadAlgorithms(self):  # noqa: N802
        self.addAlgorithm(FillNodataAlgorithm())
        self.addAlgorithm(TerrainAlgorithm())

    def supportedOutputRasterLayerExtensions(self):  # noqa: N802
        # The tool writes any GDAL raster format; offer the same list as the GDAL provider.
        from qgis.core import QgsRasterFileWriter
        return QgsRasterFileWriter.supportedFormatExtensions()
