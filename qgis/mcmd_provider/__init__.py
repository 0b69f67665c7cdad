"""QGIS plugin entry point of the MCMD void fill Processing provider."""


def classFactory(iface):  # noqa: N802 (QGIS's name)
    """Called by QGIS (and by qgis_process, with iface None) to load the plugin."""
    from .plugin import McmdProviderPlugin

    return McmdProviderPlugin(iface)
