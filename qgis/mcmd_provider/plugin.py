"""The plugin object: it only registers the Processing provider."""

from qgis.core import QgsApplication


class McmdProviderPlugin:
    """Registers the `mcmd` Processing provider in QGIS Desktop and in qgis_process."""

    def __init__(self, iface):
        self.iface = iface
        self.provider = None

    def initProcessing(self):  # noqa: N802 (QGIS's name)
        """Called by QGIS for plugins with hasProcessingProvider=yes (also headless)."""
        if self.provider is not None:
            return
        from .provider import McmdProvider

        self.provider = McmdProvider()
        QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):  # noqa: N802 (QGIS's name)
        self.initProcessing()

    def unload(self):
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
