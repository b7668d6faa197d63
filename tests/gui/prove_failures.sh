#!/bin/bash
# Shows that gui_filter_dialog.py fails when it should: runs it against broken MeshLab
# prefixes and settings, and checks each run fails with the expected message.
#   1. no-plugin:      a prefix without libfilter_vsa.so            -> the filter is not in the menu
#   2. param-renamed:  our plugin with "Random seed" patched to "Random sead" -> a parameter is missing
#   3. apply-fails:    k = 0 typed in the dialog (the filter refuses) -> Apply adds no layer
#   4. layer-renamed:  our plugin naming its layer "... VSX k=..."   -> no "VSA k=" layer
# Usage: tests/gui/prove_failures.sh [build dir]   (the build must have made meshlab-prefix)
# Takes about two minutes; not part of ctest.
set -u
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
prefix=$build/meshlab-prefix
work=$build/tests/gui/prove_failures
rm -rf "$work" && mkdir -p "$work"

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

# Same-length byte patch of a copy of our plugin.
patched_plugin() {
  python3 - "$(readlink -f "$prefix/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_vsa.so")" "$1" "$2" "$3" <<'PY'
import sys
source, out, old, new = sys.argv[1:]
data = open(source, "rb").read()
assert len(old) == len(new) and data.count(old.encode()) == 1, (old, data.count(old.encode()))
open(out, "wb").write(data.replace(old.encode(), new.encode()))
PY
  echo "$1"
}

failures=0
expect_failure() {   # name, expected message, test arguments...
  local name=$1 expected=$2 out=$work/$1/output.txt
  shift 2
  mkdir -p "$work/$name"
  python3 "$here/gui_filter_dialog.py" --artifacts "$work/$name/artifacts" "$@" > "$out" 2>&1
  local status=$?
  if [ $status -eq 1 ] && grep -q -- "$expected" "$out"; then
    echo "ok   $name: failed as expected: $(grep '^FAIL:' "$out")"
  else
    echo "BAD  $name: exit $status, expected a failure with '$expected' (see $out)"
    failures=$((failures + 1))
  fi
}

mkdir -p "$work/param-renamed" "$work/layer-renamed"
expect_failure no-plugin "is not in Filters > Remeshing" --meshlab "$(make_prefix no-plugin "")"
expect_failure param-renamed "the dialog lacks \['Random seed'\]" --meshlab "$(make_prefix param-renamed \
  "$(patched_plugin "$work/param-renamed/libfilter_vsa.so" "Random seed" "Random sead")")"
expect_failure apply-fails "opened a window 'Filter Failure'" --meshlab "$prefix/bin/meshlab" --k 0
expect_failure layer-renamed "no layer 'fandisk VSA k=40'" --meshlab "$(make_prefix layer-renamed \
  "$(patched_plugin "$work/layer-renamed/libfilter_vsa.so" "%1 VSA k=%2" "%1 VSX k=%2")")"
[ $failures -eq 0 ] && echo "all failure cases detected" || echo "$failures case(s) not detected"
exit $failures
