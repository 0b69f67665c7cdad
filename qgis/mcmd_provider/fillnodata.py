"""The `mcmd:fillnodata` Processing algorithm: runs the mcmd_fillnodata CLI."""

import math
import os

from qgis.core import (Qgis,
                       QgsMessageLog,
                       QgsProcessing,
                       QgsProcessingException,
                       QgsProcessingParameterBand,
                       QgsProcessingParameterBoolean,
                       QgsProcessingParameterDefinition,
                       QgsProcessingParameterEnum,
                       QgsProcessingParameterNumber,
                       QgsProcessingParameterRasterDestination,
                       QgsProcessingParameterRasterLayer,
                       QgsProcessingParameterString,
                       QgsProcessingParameterVectorLayer,
                       QgsRasterFileWriter)

from . import tool
from .tool_algorithm import Progress, ToolAlgorithm, failure, file_of


# (CLI value, label) in enum order; the first is the tool's default.
METHODS = [
    ('mcmd', 'MCMD (improved, default)'),
    ('paper-ds', 'Paper, diamond-square'),
    ('paper-te', 'Paper, triangle-edge'),
]

# Δ forms (-delta), first is the tool's default.
DELTA_FORMS = [
    ('normalized', 'Normalized weighted mean (datum-independent, default)'),
    ('paper', 'Paper (pulls towards 0 when I != 0)'),
]

# Names of earlier versions -> the names shared with QGIS's gdal:fillnodata.
RENAMED = {'MAX_DISTANCE': 'DISTANCE', 'MASK': 'MASK_LAYER', 'CREATION_OPTIONS': 'OPTIONS'}

# Numeric parameters: name, CLI flag, label, type, default (= the tool's default,
# the flag is only passed when the value differs), min, max, advanced.
_DOUBLE = QgsProcessingParameterNumber.Double
_INT = QgsProcessingParameterNumber.Integer
NUMBERS = [
    ('DISTANCE', '-md', 'Maximum distance from known cells to fill, in pixels (0 = unlimited)',
     _DOUBLE, 0.0, 0.0, None, False),
    ('I', '-I', 'Paper methods only: top-down interpolation shape I', _DOUBLE, 0.0, -100.0, 100.0, True),
    ('I_BU', '-Ibu', 'Paper methods only: bottom-up interpolation shape I_bu', _DOUBLE, 0.0, -100.0, 100.0,
     True),
    ('H', '-H', 'Roughness exponent H (used with a numeric RS)', _DOUBLE, 0.5, 0.0, 1.0, True),
    ('RT', '-rt', 'Paper methods only: displacement bias rt (used when RS is not 0)', _DOUBLE, 0.0, -1.0,
     1.0, True),
    ('SEED', '-seed', 'Random seed (used when RS is not 0)', _INT, 0, 0, None, True),
    ('TILE_SIZE', '-tile', 'Tile size in pixels, 2^n+1 (0 = automatic)', _INT, 0, 0, None, True),
    ('THREADS', '-threads', 'Number of threads (0 = the tool\'s default)', _INT, 0, 0, 1024, True),
]


class FillNodataAlgorithm(ToolAlgorithm):
    SHORT_HELP = ('Fills nodata voids of a raster (DEM) with Morphologically Constrained Midpoint '
                  'Displacement by running the mcmd_fillnodata tool. Known cells are never changed. '
                  'RS 0 gives a smooth fill; RS auto, a number or an amplitude such as 20m adds '
                  'terrain-like roughness (H, seed).')
    # The full help, an HTML page shipped in the plugin (also the help URL).
    HELP_FILE = tool.help_file('fillnodata')
    HELP = tool.read_help(HELP_FILE)
    RENAMED = RENAMED
    RENAMED_AS = 'as gdal:fillnodata'

    INPUT = 'INPUT'
    BANDS = 'BANDS'
    BAND = 'BAND'              # gdal:fillnodata's name: one band, added to BANDS
    ITERATIONS = 'ITERATIONS'  # gdal:fillnodata's smoothing passes: not needed, ignored
    MASK = 'MASK_LAYER'
    NO_MASK = 'NO_MASK'
    METHOD = 'METHOD'
    DELTA = 'DELTA'
    RS = 'RS'
    INNER_ONLY = 'INNER_ONLY'
    FILL_FROM = 'FILL_FROM'
    MAX_VOID = 'MAX_VOID'
    MORPH = 'MORPH'
    RIVERS = 'RIVERS'
    RIDGES = 'RIDGES'
    CREATION_OPTIONS = 'OPTIONS'
    EXTRA = 'EXTRA'
    OUTPUT = 'OUTPUT'

    def createInstance(self):  # noqa: N802
        return FillNodataAlgorithm()

    def name(self):
        return 'fillnodata'

    def displayName(self):  # noqa: N802
        return self.tr('Fill nodata (MCMD)')

    def group(self):
        return self.tr('Raster analysis')

    def groupId(self):  # noqa: N802
        return 'rasteranalysis'

    def tags(self):
        return self.tr('dem,void,nodata,fill,interpolate,midpoint,displacement,fractal,'
                       'terrain,srtm,mcmd').split(',')

    def shortDescription(self):  # noqa: N802
        return self.tr('Fills raster nodata voids with MCMD (mcmd_fillnodata).')

    def initAlgorithm(self, config=None):  # noqa: N802
        self.addParameter(QgsProcessingParameterRasterLayer(
            self.INPUT, self.tr('Input layer')))
        self.addParameter(QgsProcessingParameterBand(
            self.BANDS, self.tr('Bands to fill (empty: all bands)'), None,
            parentLayerParameterName=self.INPUT, optional=True, allowMultiple=True))
        # Hidden: accepted so that models and scripts made with gdal:fillnodata run as they are.
        band = QgsProcessingParameterBand(self.BAND, self.tr('Band to fill (as gdal:fillnodata)'), None,
                                          parentLayerParameterName=self.INPUT, optional=True)
        iterations = QgsProcessingParameterNumber(
            self.ITERATIONS, self.tr('Smoothing iterations (as gdal:fillnodata; not needed, ignored)'),
            type=QgsProcessingParameterNumber.Integer, defaultValue=0, minValue=0)
        for param in (band, iterations):
            param.setFlags(param.flags() | QgsProcessingParameterDefinition.FlagHidden)
            self.addParameter(param)
        self.addParameter(QgsProcessingParameterRasterLayer(
            self.MASK, self.tr('Validity mask (0 = void to fill)'), optional=True))
        no_mask = QgsProcessingParameterBoolean(
            self.NO_MASK, self.tr('Do not use the default validity mask of the input'),
            defaultValue=False)
        no_mask.setFlags(no_mask.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        self.addParameter(no_mask)
        self.addParameter(QgsProcessingParameterEnum(
            self.METHOD, self.tr('Method'), options=[self.tr(label) for _, label in METHODS],
            defaultValue=0))
        for name, _flag, label, kind, default, minimum, maximum, advanced in NUMBERS:
            param = QgsProcessingParameterNumber(name, self.tr(label), type=kind,
                                                 defaultValue=default)
            if minimum is not None:
                param.setMinimum(minimum)
            if maximum is not None:
                param.setMaximum(maximum)
            if advanced:
                param.setFlags(param.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
            if kind == _DOUBLE:
                param.setMetadata({'widget_wrapper': {'decimals': 2}})
            self.addParameter(param)
            if name == 'I_BU':
                delta = QgsProcessingParameterEnum(
                    self.DELTA, self.tr('Paper methods only: Δ form (how parents are averaged)'),
                    options=[self.tr(label) for _, label in DELTA_FORMS], defaultValue=0)
                delta.setFlags(delta.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
                self.addParameter(delta)
            if name == 'DISTANCE':
                # RS right after the distance: the two options users change most.
                self.addParameter(QgsProcessingParameterString(
                    self.RS, self.tr('Displacement scale RS (0 = smooth, a number, or "auto")'),
                    defaultValue='0'))
                self.addParameter(QgsProcessingParameterBoolean(
                    self.INNER_ONLY, self.tr('Fill only inner holes (leave voids touching the border)'),
                    defaultValue=False))
                self.addParameter(QgsProcessingParameterRasterLayer(
                    self.FILL_FROM, self.tr('Second DEM to take the voids\' shape from (delta surface fill)'),
                    optional=True))
                self.addParameter(QgsProcessingParameterString(
                    self.MAX_VOID, self.tr('Leave voids larger than (cells, or an area: 2.5km2, 40ha; 0 = no cap)'),
                    defaultValue='0'))
                self.addParameter(QgsProcessingParameterBoolean(
                    self.MORPH, self.tr('Carry valleys through the voids, no filled pit (for hydrology)'),
                    defaultValue=False))
                for name, label in ((self.RIVERS, 'River lines the fill follows through the voids'),
                                    (self.RIDGES, 'Ridge lines the fill follows through the voids')):
                    self.addParameter(QgsProcessingParameterVectorLayer(
                        name, self.tr(label), [QgsProcessing.TypeVectorLine], optional=True))
        options = QgsProcessingParameterString(
            self.CREATION_OPTIONS, self.tr('Creation options'), defaultValue='', optional=True)
        options.setFlags(options.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        # The GDAL provider's creation-option editor, when the Processing plugin offers it.
        options.setMetadata({'widget_wrapper': {
            'class': 'processing.algs.gdal.ui.RasterOptionsWidget.RasterOptionsWidgetWrapper'}})
        self.addParameter(options)
        extra = QgsProcessingParameterString(
            self.EXTRA, self.tr('Additional command-line parameters'), defaultValue=None,
            optional=True)
        extra.setFlags(extra.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        self.addParameter(extra)
        self.addParameter(QgsProcessingParameterRasterDestination(
            self.OUTPUT, self.tr('Filled')))

    # ---- parameter checks -------------------------------------------------

    @staticmethod
    def parse_rs(text):
        """'auto', a finite number >= 0 or one with the suffix m (an amplitude in elevation
        units: 20m), as the CLI spells it; None when invalid. The CLI checks the ranges."""
        text = (text or '').strip()
        if text.lower() == 'auto':
            return 'auto'
        if not text:
            return '0'
        number = text[:-1].strip() if text[-1] in 'mM' else text
        try:
            value = float(number)
        except ValueError:
            return None
        if not math.isfinite(value) or value < 0:
            return None
        return number + 'm' if number != text else text

    @staticmethod
    def rs_is_zero(rs):
        return rs != 'auto' and float(rs.rstrip('m')) == 0.0

    def checkParameterValues(self, parameters, context):  # noqa: N802
        ok, message = super().checkParameterValues(parameters, context)
        if not ok:
            return ok, message
        rs = self.parameterAsString(parameters, self.RS, context)
        if self.parse_rs(rs) is None:
            return False, self.tr('RS must be "auto", a number >= 0 or an amplitude in elevation units '
                                  '(e.g. 20m), not "{}"').format(rs)
        tile = self.parameterAsInt(parameters, 'TILE_SIZE', context)
        if tile and (tile < 3 or (tile - 1) & (tile - 2)):
            return False, self.tr('Tile size must be 0 (automatic) or 2^n+1 (e.g. 257, 1025, '
                                  '2049), not {}').format(tile)
        return True, ''

    # ---- command line -----------------------------------------------------

    @staticmethod
    def _number_text(value, kind):
        if kind == _INT:
            return str(int(value))
        return repr(float(value)) if not float(value).is_integer() else str(int(value))

    def build_command(self, parameters, context, feedback, executable):
        """The argument list, like GdalAlgorithm.getConsoleCommands but as a list."""
        layer = self.parameterAsRasterLayer(parameters, self.INPUT, context)
        if layer is None:
            raise QgsProcessingException(self.invalidRasterError(parameters, self.INPUT))
        if layer.providerType() != 'gdal':
            raise QgsProcessingException(self.tr(
                'The input layer must be a file GDAL can read (its provider is "{}"); save it '
                'as a GeoTIFF first.').format(layer.providerType()))
        source = layer.source()

        args = [executable]

        bands = self.parameterAsInts(parameters, self.BANDS, context)
        if parameters.get(self.BAND) not in (None, ''):
            band = self.parameterAsInt(parameters, self.BAND, context)
            bands += [] if band in bands else [band]
        for band in bands:
            if band < 1 or band > layer.bandCount():
                raise QgsProcessingException(self.tr(
                    'Band {} does not exist; the input has {} band(s).').format(
                        band, layer.bandCount()))
            args += ['-b', str(band)]

        mask = self.parameterAsRasterLayer(parameters, self.MASK, context)
        if mask is not None:
            args += ['-mask', mask.source()]
        if self.parameterAsBoolean(parameters, self.NO_MASK, context):
            args.append('-nomask')

        method = METHODS[self.parameterAsEnum(parameters, self.METHOD, context)][0]
        if method != METHODS[0][0]:
            args += ['-method', method]

        for name, flag, _label, kind, default, _min, _max, _adv in NUMBERS:
            if kind == _INT:
                value = self.parameterAsInt(parameters, name, context)
            else:
                value = self.parameterAsDouble(parameters, name, context)
            if value != default:
                args += [flag, self._number_text(value, kind)]
            if name == 'I_BU':
                delta = DELTA_FORMS[self.parameterAsEnum(parameters, self.DELTA, context)][0]
                if delta != DELTA_FORMS[0][0]:
                    args += ['-delta', delta]
            if name == 'DISTANCE':
                rs = self.parse_rs(self.parameterAsString(parameters, self.RS, context))
                if rs is None:
                    raise QgsProcessingException(self.tr('RS must be "auto", a number >= 0 or e.g. 20m'))
                if not self.rs_is_zero(rs):
                    args += ['-rs', rs]
                second = self.parameterAsRasterLayer(parameters, self.FILL_FROM, context)
                if second is not None:
                    args += ['-fill-from', second.source()]
                if self.parameterAsBoolean(parameters, self.INNER_ONLY, context):
                    args.append('-inner')
                max_void = (self.parameterAsString(parameters, self.MAX_VOID, context) or '').strip()
                if max_void not in ('', '0'):
                    args += ['-maxvoid', max_void]  # the tool checks it and says what is wrong
                if self.parameterAsBoolean(parameters, self.MORPH, context):
                    args += ['-morph', 'auto']
                for name, flag, what in ((self.RIVERS, '-rivers', 'river'), (self.RIDGES, '-ridges', 'ridge')):
                    lines = self.parameterAsVectorLayer(parameters, name, context)
                    if lines is not None:
                        args += [flag, file_of(lines, what + ' lines')]

        output = self.parameterAsOutputLayer(parameters, self.OUTPUT, context)
        if not output:
            raise QgsProcessingException(self.tr('No output file given.'))
        if os.path.abspath(output) == os.path.abspath(source.split('|')[0]):
            raise QgsProcessingException(self.tr(
                'The output must differ from the input (the input is never overwritten).'))
        driver = QgsRasterFileWriter.driverForExtension(os.path.splitext(output)[1]) or 'GTiff'
        args += ['-of', driver]

        options = self.parameterAsString(parameters, self.CREATION_OPTIONS, context)
        for option in (options or '').split('|'):
            option = option.strip()
            if option:
                args += ['-co', option]

        extra = self.parameterAsString(parameters, self.EXTRA, context)
        if extra and extra.strip():
            import shlex
            args += shlex.split(extra)

        args += [source, output]
        return args, output

    # ---- run --------------------------------------------------------------

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        try:
            executable = tool.find_executable()
        except tool.ToolError as err:
            raise QgsProcessingException(str(err)) from err
        args, output = self.build_command(parameters, context, feedback, executable)

        command = tool.command_string(args)
        QgsMessageLog.logMessage(command, 'Processing', Qgis.Info)
        feedback.pushInfo(self.tr('mcmd_fillnodata command:'))
        feedback.pushCommandInfo(command)
        feedback.pushInfo(self.tr('mcmd_fillnodata command output:'))

        out_dir = os.path.dirname(os.path.abspath(output))
        if out_dir and not os.path.isdir(out_dir):
            os.makedirs(out_dir, exist_ok=True)
        before = tool.snapshot(out_dir)

        def warn(line):
            if hasattr(feedback, 'pushWarning'):
                feedback.pushWarning(line)
            else:  # pragma: no cover (QGIS < 3.16)
                feedback.reportError(line, False)

        iterations = self.parameterAsInt(parameters, self.ITERATIONS, context)
        if iterations:
            warn(self.tr('ITERATIONS={} is ignored: the smoothing passes of gdal:fillnodata are not needed, '
                         'the fill is smooth and meets the rim without a seam.').format(iterations))

        progress = Progress(feedback)
        try:
            messages = tool.run(args,
                                on_progress=progress,
                                on_info=feedback.pushConsoleInfo,
                                is_canceled=feedback.isCanceled)
        except tool.ToolError as err:
            for line in err.lines:
                if line != str(err):
                    warn(line)
            removed = tool.remove_outputs(output, before)
            for path in removed:
                feedback.pushInfo(self.tr('Removed {}').format(path))
            raise failure(str(err), feedback, progress) from err
        for line in messages:
            warn(line)
        if not os.path.exists(output):
            raise QgsProcessingException(self.tr(
                'mcmd_fillnodata finished but wrote no output at {}').format(output))
        feedback.setProgress(100)
        # Name the loaded result after its input ("dem filled"), not the output's label.
        if context.willLoadLayerOnCompletion(output):
            layer = self.parameterAsRasterLayer(parameters, self.INPUT, context)
            if layer is not None:
                context.layerToLoadOnCompletionDetails(output).name = self.tr('{} filled').format(layer.name())
        return {self.OUTPUT: output}
