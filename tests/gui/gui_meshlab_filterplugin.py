#!/usr/bin/env python3
"""GUI test of our FilterPlugin build in the real MeshLab 2025.07 application, under its own Xvfb.

The plugin is installed as a user installs it, in a private HOME: into MeshLab's extra-plugins
folder ~/.local/share/VCG/MeshLab_64bit_fp/MeshLabExtraPlugins/<version>/
(MeshLabApplication::extraPluginsLocation(), "_dp" for a double-precision MeshLab), either copied
there before MeshLab starts (--install copy) or through Help > Plugin Info > Load Plugins and
MeshLab's file dialog (--install load-plugins), which checks the plugin and copies it there
itself. With --archive the plugin is the one in our release archive for this MeshLab, unpacked
first as a user does. Then, as in the 2020.09 test (meshlab_gui.py): Filters > Remeshing, Simplification and
Reconstruction > Variational Shape Approximation, every parameter in the dialog, the number of
proxies typed, Apply, the new layer "<mesh> VSA k=<k>" in the layer panel and our log line, and
the input layer hidden (a closed eye in the layer panel) while the new one is shown.

It fails when MeshLab cannot load the plugin, when Load Plugins does not install it, when the
filter is missing from the menu, when the dialog lacks a parameter, when Apply adds no layer, and
when the input is still shown after Apply. Screenshots of every step stay in --artifacts; their
paths are printed. Exit status: 0 pass, 1 fail, 77 skip (a needed tool is missing).
"""
import shutil
import subprocess
import sys
from pathlib import Path

import meshlab_gui
from meshlab_gui import TestFailure, find_line, log, norm


def extra_plugins_folder(home, version, scalar):
    """MeshLabApplication::extraPluginsLocation(): QStandardPaths' AppDataLocation, that is
    ~/.local/share/<organization>/<application name>, + MeshLabExtraPlugins/<MESHLAB_VERSION>;
    main.cpp names the application MeshLab_<word size>bit_<fp or dp> and the organization VCG."""
    precision = "dp" if scalar == "double" else "fp"
    return Path(home) / ".local/share/VCG" / f"MeshLab_64bit_{precision}" / "MeshLabExtraPlugins" / version


def load_plugins(session, main, folder):
    """Help > Plugin Info > Load Plugins, the plugin's path typed into the file dialog; checks
    that MeshLab copied it into `folder` and lists it, and closes the dialog (MeshLab then adds
    the plugin's filters to its menus)."""
    args = session.args
    help_menu = meshlab_gui.open_menu(session, main, "Help", "alt+h")
    entry, lines, shot = session.menu_entry(help_menu, "menu_help", "Plugin Info")
    if entry is None:
        raise TestFailure(f"no 'Plugin Info' in the Help menu ({shot}, read: {session.dump(lines, 'menu_help')})")
    session.click(entry.center)
    info = session.wait_for(lambda: session.windows("^Plugin Information$")[:1], 10,
                            "the 'Plugin Information' dialog")[0]
    # Each window is read once it is painted (the machine may be busy): until OCR finds its text.
    lines = session.wait_for(lambda: read_if(session, info, "plugin_info", "Load Plugins"), 10,
                             "Plugin Information's 'Load Plugins' button")
    loaded_before = plugins_loaded(lines)
    session.click(find_line(lines, "Load Plugins", max_prefix=0).center)
    dialog = session.wait_for(lambda: session.windows("^Load Plugins$")[:1], 10, "the 'Load Plugins' file dialog")[0]
    session.wait_for(lambda: read_if(session, dialog, "load_plugins_dialog", "Look in", "File name", "Files of type"),
                     10, "the file dialog's 'Look in', 'File name' or 'Files of type'")
    # Qt's own file dialog (no desktop here) starts in its file name field: a full path is taken.
    path = str(Path(args.plugin).resolve())
    session.x("xdotool", "type", "--delay", "20", path)
    session.wait_for(lambda: read_if(session, dialog, "load_plugins_typed", Path(path).name, anywhere=True), 10,
                     f"the file dialog to show the typed path {path}")
    session.x("xdotool", "key", "Return")
    copied = folder / Path(args.plugin).name

    def installed():
        # PluginManager::checkPlugin refusing the plugin: a box, and no copy.
        for box in session.windows("^Error while loading plugin"):
            raise TestFailure(f"Load Plugins refused the plugin: {session.window_text(box, 'load_error')}")
        return copied.is_file() and not session.windows("^Load Plugins$")
    session.wait_for(installed, 10, f"MeshLab to copy the plugin to {copied}")

    def listing():
        # Also its plugin count: a file dialog still painted over it shows the file name too
        # (its completer), which a busy machine once gave OCR to read instead.
        lines = read_if(session, info, "plugin_info_loaded", copied.name, anywhere=True)
        return lines if lines and plugins_loaded(lines) is not None else None
    lines = session.wait_for(listing, 10, f"Plugin Information to list {copied.name} and its plugin count")
    if plugins_loaded(lines) != loaded_before + 1:
        raise TestFailure(f"Plugin Information counted {plugins_loaded(lines)} plugins after Load Plugins, "
                          f"{loaded_before} before")
    log(f"Load Plugins copied the plugin to {copied}; Plugin Information lists it "
        f"({loaded_before} plugins before, {loaded_before + 1} after)")
    # Escape closes it as its OK button does (whose icon keeps OCR from reading it).
    session.x("xdotool", "windowfocus", str(info), check=False)
    session.x("xdotool", "key", "Escape")
    session.wait_for(lambda: not session.windows("^Plugin Information$"), 10, "Plugin Information to close")


def read_if(session, window, name, *texts, anywhere=False):
    """What OCR reads in `window` if it shows one of `texts` (at the start of a line, or
    `anywhere`), else None."""
    lines, _ = session.ocr_window(window, name)
    for text in texts:
        if any(norm(text) in norm(l.text) for l in lines) if anywhere else find_line(lines, text, max_prefix=0):
            return lines
    return None


def plugins_loaded(lines):
    """The number in Plugin Information's 'Number of plugin loaded: N' (None if not read)."""
    line = find_line(lines, "Number of plugin loaded", max_prefix=0)
    digits = norm(line.text)[len(norm("Number of plugin loaded")):] if line else ""
    return int(digits) if digits.isdigit() else None


def unpack_archive(session):
    """--archive unpacked into the artifacts' download/ folder; its one libfilter_vsa.so becomes
    --plugin (the archive's layout: <name>/libfilter_vsa.so, LICENSE, README.txt)."""
    args = session.args
    download = session.artifacts / "download"
    shutil.rmtree(download, ignore_errors=True)
    download.mkdir()
    subprocess.run(["tar", "-xzf", args.archive, "-C", str(download)], check=True)
    plugins = sorted(download.glob("*/libfilter_vsa.so"))
    if len(plugins) != 1 or not (plugins[0].parent / "README.txt").is_file():
        raise TestFailure(f"{args.archive} holds {[str(p.relative_to(download)) for p in plugins]} "
                          "instead of one <name>/libfilter_vsa.so next to a README.txt")
    args.plugin = str(plugins[0])
    log(f"unpacked {Path(args.archive).name}: {plugins[0].relative_to(download)}")


def run(session):
    args = session.args
    if args.archive:
        unpack_archive(session)
    home = session.make_home()
    folder = extra_plugins_folder(home, args.version, args.scalar)
    if args.install == "copy":
        folder.mkdir(parents=True)
        shutil.copy2(args.plugin, folder)
        log(f"installed {args.plugin} as {folder / Path(args.plugin).name}")
    if args.install == "load-plugins":
        meshlab_gui.run_filter_dialog(session, after_start=lambda main: load_plugins(session, main, folder))
    else:
        meshlab_gui.run_filter_dialog(session)


def add_arguments(parser):
    plugin = parser.add_mutually_exclusive_group(required=True)
    plugin.add_argument("--plugin", help="our plugin built for this MeshLab (libfilter_vsa.so)")
    plugin.add_argument("--archive", help="our release archive for this MeshLab (.tar.gz)")
    parser.add_argument("--version", required=True, help="the MeshLab's MESHLAB_VERSION (2025.07, 2025.07d)")
    parser.add_argument("--scalar", choices=("float", "double"), default="float", help="its MESHLAB_SCALAR")
    parser.add_argument("--install", choices=("copy", "load-plugins"), default="copy",
                        help="copy the plugin into the extra-plugins folder, or install it with Load Plugins")


if __name__ == "__main__":
    sys.exit(meshlab_gui.main(__doc__, run, add_arguments))
