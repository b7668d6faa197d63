"""What the GUI tests of the VSA filter in the real MeshLab share (gui_filter_dialog.py: MeshLab
2020.09; gui_meshlab_filterplugin.py: MeshLab 2025.07): their own Xvfb, MeshLab started in a
private HOME, xdotool for the mouse and keys, tesseract OCR to find what is on the screen, and the
steps from the opened mesh to the new layer (run_filter_dialog).

The filter is reached as a user does: Filters > Remeshing, Simplification and Reconstruction >
Variational Shape Approximation with the mouse, every entry found by OCR in a capture of the
menu's own window rather than at fixed pixels; the parameter dialog must show every parameter;
the number of proxies is typed; Apply must add a layer "<mesh> VSA k=<k>" to the layer panel and
the line 'VSA: added layer' to the log, and hide the input (a closed eye in the layer list, the new
layer's open) so the two do not overlap in the view.

Python 3 standard library only; needs Xvfb, xdotool, ImageMagick (import, convert) and
tesseract (tesseract-ocr with its English data).
"""
import argparse
import colorsys
import difflib
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

MENU = "Filters"
SUBMENU = "Remeshing, Simplification and Reconstruction"
FILTER = "Variational Shape Approximation"
# Every parameter's description, as the dialog shows it (filter_vsa/vsa_parameters.cpp).
PARAMETERS = [
    "Number of proxies (k)",
    "Target error (0 = use k)",
    "Metric",
    "Initialization",
    "Max iterations",
    "Random seed",
    "Teleport proxies",
    "Anchor threshold",
    "Project anchors on proxies",
    "Polygonal output",
    "Colorize regions on the input",
    "Add anchor layer",
]
REQUIRED_TOOLS = ["Xvfb", "xdotool", "import", "convert", "tesseract"]


class TestFailure(Exception):
    pass


def log(message):
    print(f"[{Path(sys.argv[0]).stem} {time.strftime('%H:%M:%S')}] {message}", flush=True)


def norm(text):
    """What OCR gets reliably: lower-case letters and digits only."""
    return re.sub(r"[^a-z0-9]", "", text.lower())


# ----------------------------------------------------------------------------------------
# OCR
class Word:
    def __init__(self, text, left, top, width, height):
        self.text, self.left, self.top, self.width, self.height = text, left, top, width, height

    @property
    def center(self):
        return (round(self.left + self.width / 2), round(self.top + self.height / 2))


class Line:
    def __init__(self, words):
        self.words = words
        self.text = " ".join(w.text for w in words)
        self.left = min(w.left for w in words)
        self.top = min(w.top for w in words)
        self.right = max(w.left + w.width for w in words)
        self.bottom = max(w.top + w.height for w in words)

    @property
    def center(self):
        return (round((self.left + self.right) / 2), round((self.top + self.bottom) / 2))

    def __repr__(self):
        return f"{self.text!r}@({self.left},{self.top})"


def ocr(png, work_dir, scale=2, origin=(0, 0), crop=None, threshold=None):
    """Lines of text in `png`, in screen coordinates (the image's top-left is at `origin`), or
    in its part `crop` = (x, y, width, height) only.

    The image is made grey and enlarged `scale` times first: MeshLab's small fonts (the log's
    in particular) read much better that way. Cropping to one panel keeps tesseract from
    mixing the lines of neighbouring panels. A `threshold` (percent) turns the image black and
    white, which reads the white-on-blue row of the selected layer better."""
    scaled = Path(work_dir) / "ocr" / f"input_x{scale}.png"   # what tesseract read last
    scaled.parent.mkdir(exist_ok=True)
    command = ["convert", str(png)]
    if crop:
        x, y, w, h = crop
        command += ["-crop", f"{w}x{h}+{x}+{y}", "+repage"]
        origin = (origin[0] + x, origin[1] + y)
    command += ["-colorspace", "Gray", "-resize", f"{scale * 100}%"]
    if threshold:
        command += ["-threshold", f"{threshold}%"]
    subprocess.run(command + [str(scaled)], check=True)
    # One thread: tesseract's OpenMP threads make it several times slower on small images.
    env = dict(os.environ, OMP_THREAD_LIMIT="1")
    tsv = subprocess.run(["tesseract", str(scaled), "stdout", "--psm", "3", "tsv"], check=True, env=env,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout
    groups = {}
    for row in tsv.splitlines()[1:]:
        fields = row.split("\t")
        if len(fields) != 12 or fields[0] != "5" or not fields[11].strip():
            continue
        left, top, width, height = (int(v) for v in fields[6:10])
        word = Word(fields[11].strip(), origin[0] + left / scale, origin[1] + top / scale, width / scale,
                    height / scale)
        groups.setdefault(tuple(fields[1:5]), []).append(word)
    return [Line(words) for words in groups.values()]


def find_line(lines, label, max_prefix=2):
    """The line that starts with `label` (after at most `max_prefix` stray characters, such as a
    check box read as 'v'), comparing letters and digits only; None if there is none."""
    target = norm(label)
    for line in lines:
        position = norm(line.text).find(target)
        if 0 <= position <= max_prefix:
            return line
    return None


# ----------------------------------------------------------------------------------------
# X: processes, windows, screenshots, input
class Session:
    def __init__(self, args):
        self.args = args
        self.artifacts = Path(args.artifacts).resolve()   # HOME and cwd of MeshLab, so absolute
        self.display = None
        self.xvfb = None
        self.meshlab = None
        self.home_made = False
        self.shots = []

    # -- processes
    def start_xvfb(self):
        read_fd, write_fd = os.pipe()
        self.xvfb = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_fd), "-screen", "0", f"{self.args.width}x{self.args.height}x24",
             "-nolisten", "tcp", "-noreset"],
            pass_fds=(write_fd,), stdout=subprocess.DEVNULL, stderr=open(self.artifacts / "xvfb.log", "w"))
        os.close(write_fd)
        # -displayfd: Xvfb picks a free display itself and writes its number once it is ready.
        deadline = time.time() + 15
        number = b""
        os.set_blocking(read_fd, False)
        while time.time() < deadline and not number.endswith(b"\n"):
            try:
                chunk = os.read(read_fd, 16)
                if not chunk:
                    break
                number += chunk
            except BlockingIOError:
                if self.xvfb.poll() is not None:
                    break
                time.sleep(0.05)
        os.close(read_fd)
        if not number.strip().isdigit():
            raise TestFailure(f"Xvfb did not start (see {self.artifacts / 'xvfb.log'})")
        self.display = f":{number.strip().decode()}"
        log(f"Xvfb on display {self.display} ({self.args.width}x{self.args.height})")

    @property
    def home(self):
        return self.artifacts / "home"

    def make_home(self):
        """A fresh HOME: no saved settings or layout, no first-use boxes, no user plugins."""
        shutil.rmtree(self.home, ignore_errors=True)
        (self.home / ".config").mkdir(parents=True)
        (self.home / "runtime").mkdir(mode=0o700)
        self.home_made = True
        return self.home

    def start_meshlab(self):
        """MeshLab on the mesh, in the HOME of make_home (made now if this session has not yet)."""
        if not self.home_made:
            self.make_home()
        home = self.home
        env = dict(os.environ, DISPLAY=self.display, HOME=str(home), XDG_CONFIG_HOME=str(home / ".config"),
                   XDG_RUNTIME_DIR=str(home / "runtime"), QT_QPA_PLATFORM="xcb")
        # A user's data folder is ~/.local/share: MeshLab 2025.07 looks for their plugins below it.
        for name in ("WAYLAND_DISPLAY", "XDG_DATA_HOME"):
            env.pop(name, None)
        self.meshlab = subprocess.Popen([self.args.meshlab, self.args.mesh], env=env, cwd=self.artifacts,
                                        stdin=subprocess.DEVNULL, stdout=open(self.artifacts / "meshlab.log", "w"),
                                        stderr=subprocess.STDOUT, start_new_session=True)
        log(f"started {self.args.meshlab} {self.args.mesh} (pid {self.meshlab.pid})")

    def stop(self):
        for process in (self.meshlab, self.xvfb):
            if process is None or process.poll() is not None:
                continue
            process.terminate()
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()

    def check_alive(self):
        if self.meshlab.poll() is not None:
            raise TestFailure(f"MeshLab exited (status {self.meshlab.returncode}); "
                              f"its output: {self.artifacts / 'meshlab.log'}")

    # -- X tools
    def x(self, *command, check=True):
        result = subprocess.run(list(command), env=dict(os.environ, DISPLAY=self.display), check=False,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=30)
        if check and result.returncode != 0:
            raise TestFailure(f"{' '.join(command)} failed: {result.stderr.strip()}")
        return result.stdout

    def windows(self, name=""):
        """Visible top-level windows whose name matches the regular expression `name`."""
        out = self.x("xdotool", "search", "--onlyvisible", "--maxdepth", "1", "--name", name, check=False)
        return [int(w) for w in out.split()]

    def geometry(self, window):
        values = dict(line.split("=", 1) for line in
                      self.x("xdotool", "getwindowgeometry", "--shell", str(window)).split())
        return int(values["X"]), int(values["Y"]), int(values["WIDTH"]), int(values["HEIGHT"])

    def window_name(self, window):
        return self.x("xdotool", "getwindowname", str(window), check=False).strip()

    def wait_for(self, condition, timeout, what, interval=0.2):
        deadline = time.time() + timeout
        while True:
            self.check_alive()
            value = condition()
            if value:
                return value
            if time.time() > deadline:
                raise TestFailure(f"timed out after {timeout} s waiting for {what}")
            time.sleep(interval)

    def new_popup(self, before, timeout=5):
        """The window that appeared since `before` (a menu is a top-level override-redirect window)."""
        def appeared():
            fresh = [w for w in self.windows() if w not in before]
            inside = []
            for window in fresh:
                x, y, w, h = self.geometry(window)
                if w > 20 and h > 20 and x >= 0 and y >= 0 and x + w <= self.args.width and y + h <= self.args.height:
                    inside.append(window)
            return max(inside) if inside else None   # the newest (X ids grow)
        return self.wait_for(appeared, timeout, "a menu to open")

    def shot(self, name, window="root"):
        path = self.artifacts / f"{name}.png"
        self.x("import", "-window", str(window), str(path))
        self.shots.append(path)
        return path

    def click(self, point):
        x, y = point
        self.x("xdotool", "mousemove", str(x), str(y))
        time.sleep(0.15)
        self.x("xdotool", "click", "1")

    def ocr_window(self, window, name, scale=2):
        shot = self.shot(name, window)
        origin = (0, 0) if window == "root" else self.geometry(window)[:2]
        return ocr(shot, self.artifacts, scale, origin), shot

    def menu_entry(self, menu, name, label, timeout=3):
        """The line `label` in the open `menu` window, read by OCR until it shows: a menu just
        opened may not be painted yet on a busy machine. Returns it (None if it never shows),
        the lines last read and the screenshot (<name>.png)."""
        deadline = time.time() + timeout
        origin = self.geometry(menu)[:2]
        while True:
            shot = self.shot(name, menu)
            lines = ocr(shot, self.artifacts, 2, origin)
            entry = find_line(lines, label, max_prefix=0)
            if entry is None and time.time() > deadline:   # last, read it enlarged more
                entry = find_line(ocr(shot, self.artifacts, 3, origin), label, max_prefix=0)
            if entry is not None or time.time() > deadline:
                return entry, lines, shot
            time.sleep(0.5)

    def window_text(self, window, name):
        """What OCR reads in `window` (a message box, say), and the screenshot it read."""
        lines, shot = self.ocr_window(window, name)
        return f"'{' '.join(l.text for l in lines)}' ({shot})"

    def dump(self, lines, name):
        path = self.artifacts / f"{name}.txt"
        path.write_text("".join(f"{l.left:5.0f} {l.top:5.0f}  {l.text}\n" for l in lines))
        return path


# ----------------------------------------------------------------------------------------
# The test
def layer_name(mesh, k):
    """ApproximationLayerName: QFileInfo(label).completeBaseName() + " VSA k=" + k."""
    name = Path(mesh).name
    base = name.split(".", 1)[0] if "." in name else name
    return f"{base} VSA k={k}"


def vsa_layer_rows(lines, expected):
    """Lines that show the layer `expected`: its row in the layer list (after the layer's index
    and the eye icon, before the '*' and the render-mode icons, which OCR reads as a few stray
    characters) or the current-layer label under the list; not the log's 'VSA: added layer'
    line nor the 3D view's 'Current Mesh:' line. 'k=40' must not be read into 'k=400'."""
    target = norm(expected)
    rows = []
    for line in lines:
        n = norm(line.text)
        if n.startswith(("vsa", "ysa", "currentmesh")):
            continue
        position = n.find(target)
        end = position + len(target)
        if 0 <= position <= 4 and not n[end:end + 1].isdigit():
            rows.append(line)
    return rows


def added_layer_line(line, expected):
    """The log's 'VSA: added layer "<name>"' line for about `expected`: the small log font
    sometimes reads 0 as 8 and y as v, so the line only has to be close (the layer panel's name
    is exact)."""
    n = norm(line.text)
    prefix = norm("VSA: added layer")
    return (n.startswith("vsa") and difflib.SequenceMatcher(None, n[:len(prefix)], prefix).ratio() >= 0.85 and
            difflib.SequenceMatcher(None, n[len(prefix):], norm(expected)).ratio() >= 0.85)


class MainWindow:
    """MeshLab's main window once the mesh is loaded: its X id, what OCR read on the screen, and
    the part of the screen with the layer panel and the log below it (x, y, width, height)."""
    def __init__(self, window, lines, panel):
        self.window, self.lines, self.panel = window, lines, panel


def open_mesh(session):
    """Starts MeshLab on --mesh (Xvfb first if it is not running) and waits for its layer."""
    args = session.args
    if session.display is None:
        session.start_xvfb()
    session.start_meshlab()

    # 1. The main window, made as large as the screen (there is no window manager).
    def main_window():
        # MeshLab 2025.07 says so in a box, before its main window shows, when a plugin fails to load.
        for box in session.windows("^Error while loading plugins"):
            raise TestFailure(f"MeshLab could not load a plugin: {session.window_text(box, 'plugin_error')}")
        # On its first start it asks whether it may send usage statistics: a user answers No.
        for box in session.windows("^Send Anonymous Statistics$"):
            session.shot("statistics_question", box)
            session.x("xdotool", "windowfocus", str(box), check=False)
            session.x("xdotool", "key", "--window", str(box), "alt+n")
            log("answered No to MeshLab's 'Send Anonymous Statistics' question")
            time.sleep(0.5)
        return session.windows(r"^MeshLab 20")[:1]
    main = session.wait_for(main_window, 40, "MeshLab's main window")[0]

    def full_screen():
        # Qt may still apply its own initial geometry after the window is mapped: insist.
        if session.geometry(main) != (0, 0, args.width, args.height):
            session.x("xdotool", "windowmove", str(main), "0", "0")
            session.x("xdotool", "windowsize", str(main), str(args.width), str(args.height))
            return False
        return True
    session.wait_for(full_screen, 10, "the main window to fill the screen", interval=0.5)
    base = Path(args.mesh).name.split(".", 1)[0]

    def layer_panel_anchors(lines):
        """The input's row in the layer list (its index and name) or the current-layer label
        under the list (the file name)."""
        return [l for l in lines if norm(l.text).lstrip("0123456789") in (norm(base), norm(Path(args.mesh).name))]

    def mesh_loaded():
        time.sleep(0.5)
        if session.geometry(main) != (0, 0, args.width, args.height):
            full_screen()
            return None
        lines = ocr(session.shot("start"), session.artifacts)
        return (lines, layer_panel_anchors(lines)) if layer_panel_anchors(lines) else None
    lines, anchors = session.wait_for(mesh_loaded, 30, f"the layer '{base}' in the layer panel", interval=0.5)
    if any("vsak" in norm(l.text) for l in lines):
        raise TestFailure("a 'VSA k=' layer is shown before the filter ran")
    # The layer panel (list, current-layer label, render tabs) and the log below it: from left
    # of the input's row or label to the bottom right of the screen.
    left, top = max(0, round(min(a.left for a in anchors)) - 80), 30
    panel = (left, top, args.width - left, args.height - top)
    log(f"MeshLab is up with '{base}' loaded; layer panel and log at {panel}")
    return MainWindow(main, lines, panel)


def open_menu(session, main, title, mnemonic):
    """The menu `title` of the menu bar, opened by its mnemonic key (e.g. alt+l for Fi&lters),
    else by a click on its title; returns the menu's window."""
    before = session.windows()
    session.x("xdotool", "windowfocus", str(main.window), check=False)
    session.x("xdotool", "key", mnemonic)
    try:
        return session.new_popup(before, timeout=3)
    except TestFailure:
        log(f"{mnemonic} opened no menu: clicking the menu bar's '{title}'")
        word = next((w for l in main.lines for w in l.words if l.top < 40 and norm(w.text) == norm(title)), None)
        if word is None:
            raise TestFailure(f"no '{title}' menu in the menu bar") from None
        session.click(word.center)
        return session.new_popup(before)


def open_filter_dialog(session, main):
    """Filters > Remeshing, Simplification and Reconstruction > Variational Shape Approximation;
    returns the dialog's window ("root" if it has none of its own), what OCR read in it, the
    screenshot it read and that screenshot's top-left on the screen."""
    # 2. The Filters menu, its mnemonic being Fi&lters.
    filters = open_menu(session, main, MENU, "alt+l")
    entry, lines, shot = session.menu_entry(filters, "menu_filters", SUBMENU)
    if entry is None:
        raise TestFailure(f"no '{SUBMENU}' in the {MENU} menu ({shot}, read: {session.dump(lines, 'menu_filters')})")
    before = session.windows()
    session.click(entry.center)
    try:
        submenu = session.new_popup(before)
    except TestFailure:   # MeshLab 2025.07 opens no popup for a submenu without entries
        raise TestFailure(f"'{FILTER}' is not in {MENU} > {SUBMENU}: the submenu did not open "
                          f"({session.shot('menu_remeshing')})") from None

    # 3. Our filter in that submenu.
    entry, lines, shot = session.menu_entry(submenu, "menu_remeshing", FILTER)
    if entry is None:
        raise TestFailure(f"'{FILTER}' is not in {MENU} > {SUBMENU} ({shot}, read: "
                          f"{session.dump(lines, 'menu_remeshing')})")
    log(f"found '{FILTER}' in {MENU} > {SUBMENU} at {entry.center}")
    session.click(entry.center)

    # 4. The dialog: MeshLab 2020.09 and 2025.07 show it as a floating dock titled with the filter's name.
    #    Should a later layout dock it instead, the whole screen is read in its place.
    try:
        dialog = session.wait_for(lambda: session.windows(f"^{FILTER}$")[:1], 10,
                                  f"a window titled '{FILTER}' (the parameter dialog)")[0]
    except TestFailure as no_window:
        dialog = "root"
        if find_line(ocr(session.shot("dialog"), session.artifacts), FILTER) is None:
            raise TestFailure(f"{no_window}; nor does the screen show its title "
                              f"({session.artifacts / 'dialog.png'})") from None
        log(f"no window titled '{FILTER}': reading the dialog on the whole screen")
    time.sleep(0.5)
    session.shot("dialog")
    lines, shot = session.ocr_window(dialog, "dialog_window")
    origin = (0, 0) if dialog == "root" else session.geometry(dialog)[:2]
    missing = [p for p in PARAMETERS if find_line(lines, p) is None]
    for scale in (3, 1):   # read again, enlarged differently, before calling a parameter missing
        if missing:
            again = ocr(shot, session.artifacts, scale, origin)
            missing = [p for p in missing if find_line(again, p) is None]
    if find_line(lines, FILTER) is None:
        missing.insert(0, f"(title) {FILTER}")
    if missing:
        raise TestFailure(f"the dialog lacks {missing} ({shot}, read: {session.dump(lines, 'dialog_window')})")
    log(f"the dialog shows all {len(PARAMETERS)} parameters")
    return dialog, lines, shot, origin


def apply_filter(session, main, dialog, lines, shot, origin):
    """Types --k in the open dialog (what open_filter_dialog returned), presses Apply and waits for
    the new layer in the layer panel and the log's line; returns what showed the layer, by kind
    ("list row": its row in the layer list; "name": the name alone) and the log's line."""
    args, panel = session.args, main.panel
    # 5. Number of proxies: click its field (right of the label), select all, type k, Tab.
    k = args.k
    label = find_line(lines, PARAMETERS[0]) or find_line(ocr(shot, session.artifacts, 3, origin), PARAMETERS[0])
    after = label.words[len(PARAMETERS[0].split()):]   # the value, when it was read
    field = after[-1].center if after else (round(label.right + 100), label.center[1])
    session.click(field)
    session.x("xdotool", "key", "ctrl+a")
    session.x("xdotool", "type", "--delay", "40", str(k))
    session.x("xdotool", "key", "Tab")
    time.sleep(0.4)
    lines, shot = session.ocr_window(dialog, "dialog_k")
    label = find_line(lines, PARAMETERS[0])
    if label is None or norm(label.text) != norm(PARAMETERS[0] + str(k)):
        raise TestFailure(f"could not type k={k} in '{PARAMETERS[0]}' (read {label}; {shot})")
    apply_button = next((w for l in lines for w in l.words if w.text == "Apply"), None)
    if apply_button is None:
        raise TestFailure(f"no Apply button in the dialog ({shot})")

    # Nothing from the filter yet.
    expected = layer_name(args.mesh, k)
    lines = ocr(session.shot("before_apply"), session.artifacts, crop=panel)
    if vsa_layer_rows(lines, expected) or any(norm(l.text).startswith("vsa") for l in lines):
        raise TestFailure("the layer panel or the log shows VSA output before Apply")

    # 6. Apply, then wait for the new layer and the log.
    before = set(session.windows())
    session.click(apply_button.center)
    log(f"pressed Apply with k={k}; waiting for the layer '{expected}'")
    deadline = time.time() + args.apply_timeout
    # What shows the layer, by kind: "list row" (its index, name, '*' and icons read) or "name"
    # (the name alone: the current-layer label under the list, or a row read without its index).
    found_rows, found_log, vsa_lines, attempt = {}, None, [], 0
    passes = ((2, panel, None), (3, panel, None), (2, panel, 60), (2, None, None))
    while True:
        time.sleep(0.5 if attempt == 0 else 1)
        attempt += 1
        session.check_alive()
        for window in set(session.windows()) - before:
            title = session.window_name(window)
            if title and title != FILTER and not title.startswith("MeshLab_"):
                shot = session.shot("after_apply")
                raise TestFailure(f"Apply opened a window '{title}' (a failure box?): no layer added ({shot})")
        shot = session.shot("after_apply")
        # The panel enlarged twice, three times, in black and white (the selected row is white
        # on blue); then the whole screen, in case the layout moved. Stop once all is read.
        read = []
        for scale, crop, threshold in passes:
            lines = ocr(shot, session.artifacts, scale, crop=crop, threshold=threshold)
            read.append((f"x{scale} {'panel' if crop else 'screen'}{' black&white' if threshold else ''}", lines))
            for row in vsa_layer_rows(lines, expected):
                found_rows.setdefault("name" if norm(row.text) == norm(expected) else "list row", row)
            vsa_lines = vsa_lines or [l for l in lines if norm(l.text).startswith("vsa")]
            found_log = found_log or next((l for l in lines if added_layer_line(l, expected)), None)
            if found_log and "list row" in found_rows:
                break
        if (found_log and found_rows) or time.time() > deadline:
            break
    dump = session.artifacts / "after_apply.txt"
    dump.write_text("".join(f"--- {name}\n" + "".join(f"{l.left:5.0f} {l.top:5.0f}  {l.text}\n" for l in lines)
                            for name, lines in read))
    if not found_rows:
        raise TestFailure(f"after Apply no layer '{expected}' in the layer panel ({shot}, read: {dump})")
    if not found_log:
        raise TestFailure(f"after Apply the log has no line 'VSA: added layer \"{expected}\"' ({shot}, read: {dump}; "
                          f"log lines starting with VSA: {vsa_lines})")
    log(f"the layer panel shows '{expected}' ({', '.join(f'{kind}: {row}' for kind, row in found_rows.items())}); "
        f"the log says {found_log.text!r}")
    return found_rows, found_log


def green_pixels(session, png, box, name):
    """How many clearly green pixels `box` (x, y, width, height) of the screenshot `png` holds: the
    layer list's open eye (layer_eye_open.png) has a green iris, the closed one and the rest of
    the row (white, or blue when selected) none. The crop is kept as <name>.png."""
    x, y, w, h = (round(v) for v in box)
    crop = session.artifacts / f"{name}.png"
    subprocess.run(["convert", str(png), "-crop", f"{w}x{h}+{x}+{y}", "+repage", str(crop)], check=True)
    session.shots.append(crop)
    text = subprocess.run(["convert", str(crop), "-depth", "8", "txt:-"], check=True,
                          stdout=subprocess.PIPE, text=True).stdout
    green = 0
    for row in text.splitlines()[1:]:
        r, g, b = (float(v) for v in row.split("(", 1)[1].split(")", 1)[0].split(",")[:3])
        green += g > r + 60 and g > b + 60
    return green


def warm_pixels(session, png, box, name):
    """How many pixels (of a quarter-size sample) of `box` in `png` are clearly coloured with a hue
    from red to cyan: the regions' colours. MeshLab's background (blue to purple), a layer drawn
    in white vertex colour and the grey of its shading have none. The crop is kept as <name>.png."""
    x, y, w, h = (round(v) for v in box)
    crop = session.artifacts / f"{name}.png"
    subprocess.run(["convert", str(png), "-crop", f"{w}x{h}+{x}+{y}", "+repage", "-sample", "25%", str(crop)],
                   check=True)
    session.shots.append(crop)
    text = subprocess.run(["convert", str(crop), "-depth", "8", "txt:-"], check=True,
                          stdout=subprocess.PIPE, text=True).stdout
    warm = 0
    for row in text.splitlines()[1:]:
        r, g, b = (float(v) / 255 for v in row.split("(", 1)[1].split(")", 1)[0].split(",")[:3])
        hue, saturation, value = colorsys.rgb_to_hsv(r, g, b)
        warm += saturation > 0.25 and value > 0.3 and hue < 190 / 360
    return warm


def check_regions_coloured(session, main, png):
    """The new layer is drawn in its regions' face colours (not in a uniform vertex colour): the
    3D view, left of the layer panel between the toolbars and the status text, shows them."""
    height = session.args.height
    box = (0, 0.08 * height, main.panel[0] - 10, 0.77 * height)
    warm = warm_pixels(session, png, box, "view_colours")
    log(f"3D view: {warm} sampled pixels in region colours (red to cyan)")
    if warm < 200:
        raise TestFailure(f"the new layer is not drawn in its regions' colours: {warm} coloured pixels ({png})")


def check_input_hidden(session, main, expected):
    """The input's row in the layer list shows a closed eye and the new layer's an open one. Each
    row is found by OCR (the layer's name after its index); its eye is left of the index, so the
    strip left of the name holds the expander, the eye and the index."""
    base = Path(session.args.mesh).name.split(".", 1)[0]
    shot = session.shot("layers_after_apply")
    rows = {}
    for scale, threshold in ((2, None), (3, None), (2, 60)):
        for line in ocr(shot, session.artifacts, scale, crop=main.panel, threshold=threshold):
            words = [norm(w.text) for w in line.words]
            # The name's first word, after the index (the icons may read as stray marks, which
            # norm() empties); not the label under the list nor the log, which have no index.
            at = next((i for i, w in enumerate(words)
                       if w == norm(base) and "".join(words[:i])[-1:].isdigit()), None)
            if at is None:
                continue
            # The input's name ends at its first word (what follows is the row's icons, read as
            # stray marks); the new layer's goes on with "VSA k=<k>".
            rest = "".join(words[at:])
            kind = "output" if rest.startswith(norm(expected)) else None if words[at + 1:at + 2] == ["vsa"] else "input"
            if kind and kind not in rows:
                rows[kind] = line.words[at], line
        if len(rows) == 2:
            break
    if len(rows) < 2:
        raise TestFailure(f"could not find both the input's and the new layer's rows in the layer list "
                          f"(found {sorted(rows)}; {shot})")
    green = {}
    for kind, (name, line) in rows.items():
        middle = name.top + name.height / 2
        green[kind] = green_pixels(session, shot, (name.left - 70, middle - 12, 66, 24), f"eye_{kind}")
    log(f"layer list, green pixels left of the name: input {green['input']} ({rows['input'][1]}), "
        f"new layer {green['output']} ({rows['output'][1]})")
    if green["output"] < 10:
        raise TestFailure(f"the new layer's eye is not open ({shot})")
    if green["input"] >= 10:
        raise TestFailure(f"the input layer '{base}' is still shown after Apply: its eye is open ({shot})")


def run_filter_dialog(session, after_start=None):
    """The whole way from starting MeshLab to the new layer, shown alone (the input hidden);
    after_start(main window), if given, runs once the mesh is loaded (to install a plugin, say).
    Last, a screenshot of what the user sees once the dialog is closed, in which the new layer
    must show its regions' colours."""
    main = open_mesh(session)
    if after_start:
        after_start(main)
    dialog = open_filter_dialog(session, main)
    apply_filter(session, main, *dialog)
    check_input_hidden(session, main, layer_name(session.args.mesh, session.args.k))
    close = next((w for l in dialog[1] for w in l.words if w.text == "Close"), None)
    if close:
        session.click(close.center)
        time.sleep(1)
    check_regions_coloured(session, main, session.shot("result"))


def main(description, run, add_arguments=None, default_meshlab=None):
    """A test's command line and outcome: parses the common options (and those `add_arguments`
    adds to the parser), empties --artifacts, calls run(session) and stops MeshLab and Xvfb
    whatever happens. Returns the exit status: 0 pass, 1 fail (a TestFailure), 77 skip (a tool
    is missing)."""
    root = Path(__file__).resolve().parents[2]
    parser = argparse.ArgumentParser(description=description.split("\n\n")[0])
    parser.add_argument("--meshlab", default=default_meshlab, help="the MeshLab executable")
    parser.add_argument("--mesh", default=str(root / "resources/meshes/fandisk.off"))
    parser.add_argument("--artifacts", default=str(root / "build/tests/gui" / Path(sys.argv[0]).stem),
                        help="where the screenshots and logs go (emptied of old ones first)")
    parser.add_argument("--k", type=int, default=40, help="number of proxies typed in the dialog")
    parser.add_argument("--width", type=int, default=1600)
    parser.add_argument("--height", type=int, default=1000)
    parser.add_argument("--apply-timeout", type=float, default=30, help="seconds to wait for the new layer")
    if add_arguments:
        add_arguments(parser)
    args = parser.parse_args()
    # MeshLab runs in --artifacts: paths given relative to here must still name the same files.
    args.meshlab, args.mesh = (os.path.abspath(p) if p else p for p in (args.meshlab, args.mesh))

    missing = [tool for tool in REQUIRED_TOOLS if shutil.which(tool) is None]
    if missing:
        print(f"SKIP: missing {', '.join(missing)} (Debian: xvfb xdotool imagemagick tesseract-ocr)")
        return 77
    if not args.meshlab or not os.access(args.meshlab, os.X_OK):
        print(f"FAIL: no MeshLab executable at {args.meshlab}")
        return 1

    artifacts = Path(args.artifacts)
    artifacts.mkdir(parents=True, exist_ok=True)
    for old in list(artifacts.glob("*.png")) + list(artifacts.glob("*.txt")) + list(artifacts.glob("ocr/*")):
        old.unlink()

    # ctest's timeout sends SIGTERM: turn it into an exception so MeshLab and Xvfb are stopped.
    def terminate(signum, _frame):
        raise TestFailure(f"killed by signal {signum}")
    signal.signal(signal.SIGTERM, terminate)
    signal.signal(signal.SIGHUP, terminate)

    session = Session(args)
    started = time.time()
    status = 0
    try:
        run(session)
    except TestFailure as failure:
        status = 1
        if session.display and session.xvfb and session.xvfb.poll() is None:
            try:
                session.shot("failure")
            except Exception:  # noqa: BLE001 - the screenshot is a courtesy
                pass
        print(f"FAIL: {failure}")
    finally:
        session.stop()
    print("screenshots:")
    for shot in dict.fromkeys(session.shots):
        print(f"  {shot}")
    print(f"{'PASS' if status == 0 else 'FAIL'} in {time.time() - started:.1f} s")
    return status
