"""Finding and running the mcmd_fillnodata command-line tool.

Kept free of algorithm logic so that the provider and the tests share one
implementation of: executable lookup, command logging, GDAL progress parsing,
cancellation and error reporting.
"""

import configparser
import html
import os
import queue
import re
import shlex
import shutil
import subprocess
import sys
import threading

PLUGIN_DIR = os.path.dirname(os.path.abspath(__file__))
TOOL_NAME = 'mcmd_fillnodata'
SETTING_EXECUTABLE = 'MCMD_FILLNODATA_EXECUTABLE'
ERROR_PREFIX = TOOL_NAME + ': error:'


class ToolError(Exception):
    """The tool could not be found, failed, or was cancelled.

    `lines` holds everything the tool wrote on stderr (warnings before the error).
    """

    def __init__(self, message, lines=()):
        super().__init__(message)
        self.lines = list(lines)


def plugin_version():
    parser = configparser.ConfigParser()
    try:
        parser.read(os.path.join(PLUGIN_DIR, 'metadata.txt'), encoding='utf-8')
        return parser.get('general', 'version', fallback='')
    except configparser.Error:
        return ''


def _exe_name():
    return TOOL_NAME + ('.exe' if sys.platform == 'win32' else '')


def _setting_value():
    try:
        from processing.core.ProcessingConfig import ProcessingConfig
    except ImportError:  # pragma: no cover
        return ''
    value = ProcessingConfig.getSetting(SETTING_EXECUTABLE)
    return (value or '').strip()


def find_executable(setting_value=None):
    """The tool's path, or raise ToolError saying where it was looked for.

    Order: the provider setting (a file, or a folder holding the tool), then
    bin/mcmd_fillnodata next to the plugin, then PATH.
    """
    tried = []
    configured = _setting_value() if setting_value is None else setting_value.strip()
    if configured:
        candidate = os.path.expanduser(configured)
        if os.path.isdir(candidate):
            candidate = os.path.join(candidate, _exe_name())
        if os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return candidate
        # A wrong setting is an error, not something to silently work around.
        raise ToolError(
            f'The {TOOL_NAME} executable set in Settings > Options > Processing > Providers > '
            f'MCMD void fill does not exist or is not executable: {configured}')
    bundled = os.path.join(PLUGIN_DIR, 'bin', _exe_name())
    tried.append(bundled)
    if os.path.isfile(bundled) and not os.access(bundled, os.X_OK):
        # "Install from ZIP" extracts without the executable bit.
        try:
            os.chmod(bundled, os.stat(bundled).st_mode | 0o755)
        except OSError:
            pass
    if os.path.isfile(bundled) and os.access(bundled, os.X_OK):
        return bundled
    on_path = shutil.which(TOOL_NAME)
    tried.append('PATH')
    if on_path:
        return on_path
    raise ToolError(
        f'{TOOL_NAME} was not found (looked in the provider setting, {tried[0]} and PATH). '
        f'Build it (it is at build/bin/{TOOL_NAME} after the README setup) and set its path in '
        'Settings > Options > Processing > Providers > MCMD void fill.')


def command_string(args):
    """The command as one line that can be pasted into a shell."""
    if sys.platform == 'win32':
        return subprocess.list2cmdline(args)
    return shlex.join(args)


class ProgressParser:
    """Turns GDAL's `0...10...20...30...40...50...60...70...80...90...100 - done.` into percents.

    Fed arbitrary chunks of stdout (the tool flushes after every dot, without
    newlines), it reports each new percentage through `on_progress`; any other
    text is collected into lines and given to `on_text`, and so is a finished
    progress line ("... - done.") when `echo_progress` is set (the command's
    output as a log shows it).
    """

    def __init__(self, on_progress, on_text=None, echo_progress=False):
        self.on_progress = on_progress
        self.on_text = on_text
        self.echo_progress = echo_progress
        self.percent = 0.0
        self._digits = ''
        self._line = ''
        self._in_bar = False

    def _set(self, value):
        value = max(0.0, min(100.0, value))
        if value > self.percent or (value == 0.0 and self.percent == 0.0):
            self.percent = value
            self.on_progress(value)

    def _flush_number(self):
        if not self._digits:
            return
        number = int(self._digits)
        self._digits = ''
        if 0 <= number <= 100 and number % 10 == 0:
            self._in_bar = True
            self._set(float(number))

    def feed(self, text):
        for ch in text:
            self._line += ch
            if ch.isdigit():
                self._digits += ch
                continue
            self._flush_number()
            if ch == '.' and self._in_bar:
                # GDAL prints a dot every 2.5 %: 0...10 is 0, 2.5, 5, 7.5, 10.
                self._set(self.percent + 2.5)
            elif ch == '\n':
                line = self._line.strip()
                self._line = ''
                self._in_bar = False
                self._emit(line)

    def close(self):
        self._flush_number()
        line = self._line.strip()
        self._line = ''
        self._emit(line)

    def _emit(self, line):
        # A bar is echoed only finished: one cut short by a failure would run on
        # after the progress bar qgis_process draws.
        finished_bar = self.echo_progress and line.endswith('done.')
        if line and self.on_text and (finished_bar or not _is_progress_text(line)):
            self.on_text(line)


_PROGRESS_RE = re.compile(r'^[0-9.]*(\s*-\s*done\.)?$')


def _is_progress_text(line):
    return bool(_PROGRESS_RE.match(line))


def _pump(stream, kind, out_queue):
    """Reader thread: forward raw chunks of a pipe to the queue, then None."""
    try:
        fd = stream.fileno()
        while True:
            chunk = os.read(fd, 4096)
            if not chunk:
                break
            out_queue.put((kind, chunk.decode('utf-8', errors='replace')))
    except (OSError, ValueError):
        pass
    finally:
        out_queue.put((kind, None))


def _stop(proc):
    if proc.poll() is not None:
        return
    proc.terminate()
    try:
        proc.wait(timeout=5)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def run(args, on_progress=None, on_info=None, is_canceled=None, poll_s=0.05, tool_name=TOOL_NAME):
    """Run the tool; return its stderr lines. Raise ToolError on failure or cancel.

    `on_progress(percent)`, `on_info(line)` and `is_canceled()` are called from
    the calling thread only. On cancel the process is terminated (then killed).
    The tool's stdout is echoed line by line to `on_info`, its progress bar
    only when finished.
    `tool_name` names the tool in messages (its errors start with '<name>: error:').
    """
    creationflags = 0
    if sys.platform == 'win32':  # pragma: no cover
        creationflags = getattr(subprocess, 'CREATE_NO_WINDOW', 0)
    env = dict(os.environ)
    try:
        proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, env=env, creationflags=creationflags)
    except OSError as err:
        raise ToolError(f'could not start {args[0]}: {err}') from err

    events = queue.Queue()
    threads = [threading.Thread(target=_pump, args=(proc.stdout, 'out', events), daemon=True),
               threading.Thread(target=_pump, args=(proc.stderr, 'err', events), daemon=True)]
    for thread in threads:
        thread.start()

    parser = ProgressParser(on_progress or (lambda p: None), on_info, echo_progress=True)
    err_text = ''
    open_streams = 2
    canceled = False
    try:
        while open_streams:
            if is_canceled is not None and is_canceled():
                canceled = True
                _stop(proc)
                break
            try:
                kind, text = events.get(timeout=poll_s)
            except queue.Empty:
                continue
            if text is None:
                open_streams -= 1
            elif kind == 'out':
                parser.feed(text)
            else:
                err_text += text
        if not canceled:
            proc.wait()
            # The run may have been cancelled while the last output was read.
            if is_canceled is not None and is_canceled():
                canceled = True
    finally:
        _stop(proc)
        for stream in (proc.stdout, proc.stderr):
            try:
                stream.close()
            except OSError:
                pass
    parser.close()

    err_lines = [line.rstrip() for line in err_text.splitlines() if line.strip()]
    if canceled:
        raise ToolError(f'{tool_name} was canceled.', err_lines)
    if proc.returncode != 0:
        prefix = tool_name + ': error:'
        error = next((line for line in reversed(err_lines) if line.startswith(prefix)), None)
        if error is None:
            error = err_lines[-1] if err_lines else (
                f'{tool_name} failed with exit status {proc.returncode} and no message')
        raise ToolError(error, err_lines)
    return err_lines


def snapshot(directory):
    try:
        return set(os.listdir(directory))
    except OSError:
        return set()


def remove_outputs(path, before):
    """Remove `path` and anything created beside it for it since `before` (a snapshot()).

    Catches temporary names, sidecars (.aux.xml, .ovr, .msk, .hdr...) and the
    output itself, but never a file that was in the folder before the run.
    """
    directory = os.path.dirname(os.path.abspath(path)) or '.'
    base = os.path.basename(path)
    stem = os.path.splitext(base)[0]
    removed = []
    for name in snapshot(directory) - before:
        if name.startswith((base, stem + '.', '.' + base, '.' + stem + '.')):
            full = os.path.join(directory, name)
            try:
                if os.path.isdir(full) and not os.path.islink(full):
                    shutil.rmtree(full)
                else:
                    os.remove(full)
                removed.append(full)
            except OSError:
                pass
    if os.path.lexists(path) and os.path.basename(path) not in before:
        try:
            os.remove(path)
            removed.append(path)
        except OSError:
            pass
    return removed


def help_file(name):
    """The path of an algorithm's help page, help/<name>.html in the plugin."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), 'help', name + '.html')


def read_help(path):
    """A help page as plain text: one paragraph a line.

    QGIS shows shortHelpString() twice: the dialog's panel wraps each line in
    <p> under its own title, qgis_process help prints it as it is. Plain
    lines read well in both; the page itself (with its markup) is the help URL.
    Headings and the page's title are dropped (both show the algorithm's name),
    a <dt>term</dt><dd>text</dd> becomes "term: text".
    """
    with open(path, encoding='utf-8') as f:
        text = f.read()
    start, end = text.find('<body>'), text.rfind('</body>')
    if start >= 0 and end > start:
        text = text[start + len('<body>'):end]
    text = re.sub(r'<h2>.*?</h2>', '', text, flags=re.S)
    text = re.sub(r'</dt>\s*<dd>', ': ', text)
    blocks = re.split(r'</?(?:p|dl|dt|dd|h[1-6]|ul|ol|li|br)\s*/?>', text)
    lines = [' '.join(html.unescape(re.sub(r'<[^>]+>', '', block)).split()) for block in blocks]
    return '\n'.join(line for line in lines if line)

