#!/bin/bash
# Shows that the GUI tests fail when they should: runs them against broken plugins, MeshLab
# prefixes and settings, and checks each run fails with the expected message.
# gui_filter_dialog.py, MeshLab 2020.09 (build/meshlab-prefix):
#   no-plugin:      a prefix without libfilter_vsa.so            -> the filter is not in the menu
#   param-renamed:  our plugin with "Random seed" patched to "Random sead" -> a parameter is missing
#   apply-fails:    k = 0 typed in the dialog (the filter refuses) -> Apply adds no layer
#   layer-renamed:  our plugin naming its layer "... VSX k=..."   -> no "VSA k=" layer
#   input-shown:    MeshDocument::setVisible made a no-op (LD_PRELOAD), so Apply leaves the
#                   input shown                                  -> the input's eye is open
# gui_meshlab_filterplugin.py, the MeshLab 2025.07 application of scripts/setup_filterplugin.sh:
#   fp-not-loadable:    a double-precision plugin in the float MeshLab's extra-plugins folder
#                                                                -> MeshLab cannot load it
#   fp-load-refused:    the same through Help > Plugin Info > Load Plugins -> refused
#   fp-other-plugin:    a loadable plugin that is not ours (the host tests' probe) -> not in the menu
#   fp-param-renamed, fp-apply-fails, fp-layer-renamed, fp-input-shown: as above, with our
#                       2025.07 plugin
# Usage: tests/gui/prove_failures.sh [build dir]   (the cases of a MeshLab the build lacks are
# skipped). Takes about five minutes; not part of ctest.
set -u
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
work=$build/tests/gui/prove_failures
rm -rf "$work" && mkdir -p "$work"

# Same-length byte patch of a copy of a plugin: patched_plugin SOURCE OUT OLD NEW; prints OUT.
patched_plugin() {
  python3 - "$(readlink -f "$1")" "$2" "$3" "$4" <<'PY'
import sys
source, out, old, new = sys.argv[1:]
data = open(source, "rb").read()
assert len(old) == len(new) and data.count(old.encode()) == 1, (old, data.count(old.encode()))
open(out, "wb").write(data.replace(old.encode(), new.encode()))
PY
  echo "$2"
}

# MeshDocument::setVisible(int, bool), which the plugins call to hide the input (the same symbol in
# MeshLab 2020.09 and 2025.07), doing nothing.
no_set_visible=$work/no_set_visible.so
echo 'extern "C" void _ZN12MeshDocument10setVisibleEib(void *, int, bool) {}' \
  | g++ -shared -fPIC -x c++ - -o "$no_set_visible"

failures=0
expect_failure() {   # name, expected message, test script, test arguments...
  local name=$1 expected=$2 script=$3 out=$work/$1/output.txt
  shift 3
  mkdir -p "$work/$name"
  python3 "$here/$script" --artifacts "$work/$name/artifacts" "$@" > "$out" 2>&1
  local status=$?
  if [ $status -eq 1 ] && grep -q -- "$expected" "$out"; then
    echo "ok   $name: failed as expected: $(grep '^FAIL:' "$out")"
  else
    echo "BAD  $name: exit $status, expected a failure with '$expected' (see $out)"
    failures=$((failures + 1))
  fi
}

# --- MeshLab 2020.09
prefix=$build/meshlab-prefix
# A copy of the private prefix (binary copied: MeshLab finds its plugins from its real path)
# whose filter_vsa is replaced by $2 (empty: none).
make_prefix() {
  local dir=$work/$1/prefix plugins
  plugins=$dir/lib/x86_64-linux-gnu/meshlab/plugins
  mkdir -p "$dir/bin" "$plugins"
  cp "$prefix/bin/meshlab" "$dir/bin/"
  ln -s "$(readlink -f "$prefix/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so")" \
        "$dir/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so"
  [ -e "$prefix/share" ] && cp -a "$prefix/share" "$dir/"
  for p in "$prefix"/lib/x86_64-linux-gnu/meshlab/plugins/*.so; do
    [ "$(basename "$p")" = libfilter_vsa.so ] || ln -s "$(readlink -f "$p")" "$plugins/"
  done
  [ -n "$2" ] && cp "$2" "$plugins/libfilter_vsa.so"
  echo "$dir/bin/meshlab"
}

if [ -x "$prefix/bin/meshlab" ]; then
  ours=$prefix/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_vsa.so
  mkdir -p "$work/param-renamed" "$work/layer-renamed"
  expect_failure no-plugin "is not in Filters > Remeshing" gui_filter_dialog.py \
    --meshlab "$(make_prefix no-plugin "")"
  expect_failure param-renamed "the dialog lacks \['Random seed'\]" gui_filter_dialog.py --meshlab "$(make_prefix \
    param-renamed "$(patched_plugin "$ours" "$work/param-renamed/libfilter_vsa.so" "Random seed" "Random sead")")"
  expect_failure apply-fails "opened a window 'Filter Failure'" gui_filter_dialog.py \
    --meshlab "$prefix/bin/meshlab" --k 0
  expect_failure layer-renamed "no layer 'fandisk VSA k=40'" gui_filter_dialog.py --meshlab "$(make_prefix \
    layer-renamed "$(patched_plugin "$ours" "$work/layer-renamed/libfilter_vsa.so" "%1 VSA k=%2" "%1 VSX k=%2")")"
  LD_PRELOAD=$no_set_visible expect_failure input-shown "is still shown after Apply" gui_filter_dialog.py \
    --meshlab "$prefix/bin/meshlab"
else
  echo "skip MeshLab 2020.09: no $prefix/bin/meshlab"
fi

# --- MeshLab 2025.07 (float), our plugin installed in a private HOME's extra-plugins folder
info=$here/../../.deps/meshlab-modern/current/build/meshlab-build-info.txt
app=$(sed -n 's/^application=//p' "$info" 2>/dev/null)
version=$(sed -n 's/^MESHLAB_VERSION=//p' "$info" 2>/dev/null)
tag=${version//./_}
ours=$build/filter_vsa/meshlab-$version/libfilter_vsa.so
probes=$build/tests/filterplugin_host
if [ -x "$app" ] && [ -f "$ours" ] && [ -f "$probes/libfilter_fp_probe_other_scalar_$tag.so" ]; then
  fp() {   # name, expected message, plugin, more arguments
    local name=$1 expected=$2 plugin=$3
    shift 3
    expect_failure "$name" "$expected" gui_meshlab_filterplugin.py --meshlab "$app" --version "$version" \
      --scalar float --plugin "$plugin" "$@"
  }
  mkdir -p "$work/fp-param-renamed" "$work/fp-layer-renamed"
  # The probe, compiled for the double-precision MeshLab and named as ours: what a user gets who
  # picks the wrong archive.
  wrong=$work/libfilter_vsa.so
  cp "$probes/libfilter_fp_probe_other_scalar_$tag.so" "$wrong"
  fp fp-not-loadable "MeshLab could not load a plugin" "$wrong"
  fp fp-load-refused "Load Plugins refused the plugin" "$wrong" --install load-plugins
  fp fp-other-plugin "is not in Filters > Remeshing" "$probes/libfilter_fp_probe_$tag.so"
  fp fp-param-renamed "the dialog lacks \['Random seed'\]" \
    "$(patched_plugin "$ours" "$work/fp-param-renamed/libfilter_vsa.so" "Random seed" "Random sead")"
  fp fp-apply-fails "opened a window 'Filter Failure'" "$ours" --k 0
  fp fp-layer-renamed "no layer 'fandisk VSA k=40'" \
    "$(patched_plugin "$ours" "$work/fp-layer-renamed/libfilter_vsa.so" "%1 VSA k=%2" "%1 VSX k=%2")"
  LD_PRELOAD=$no_set_visible fp fp-input-shown "is still shown after Apply" "$ours"
else
  echo "skip MeshLab $version: no application ($app), plugin ($ours) or probe plugins in $probes"
fi

[ $failures -eq 0 ] && echo "all failure cases detected" || echo "$failures case(s) not detected"
exit $failures
