#!/bin/bash
# Shows that the pymeshlab tests fail when the plugin is broken: builds the plugin for the wheel once
# per mutation of its sources (one line changed), runs pytest against it, and checks that the test
# named for that mutation fails.
# Usage: tests/pymeshlab/prove_failures.sh   (after scripts/build.sh; about 40 s per mutation)
# Not part of ctest.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$root/build/tests/pymeshlab/prove_failures
rm -rf "$work" && mkdir -p "$work"
# A copy of the sources to mutate; the dependencies are the project's own.
mkdir -p "$work/src"
(cd "$root" && git ls-files -z | xargs -0 cp --parents -t "$work/src")
ln -s "$root/.deps" "$work/src/.deps"
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
  -DVSA_FILTERPLUGIN_MESHLAB_DIR="$root/.deps/pymeshlab" > "$work/configure.log" 2>&1 \
  || { cat "$work/configure.log"; exit 2; }

failures=0
# mutate NAME FILE OLD NEW EXPECTED_FAILING_TEST
mutate() {
  local name=$1 file=$work/src/$2 old=$3 new=$4 expected=$5 out=$work/$1.txt
  cp "$root/$2" "$file"
  python3 - "$file" "$old" "$new" <<'PY' || { echo "BAD  $name: '$3' not found once in $2"; failures=$((failures + 1)); return; }
import sys
path, old, new = sys.argv[1:]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(1)
open(path, "w").write(text.replace(old, new))
PY
  if ! cmake --build "$work/build" --target filter_vsa_fp_2025_07d -j2 > "$out" 2>&1; then
    echo "BAD  $name: the mutant does not build (see $out)"; failures=$((failures + 1))
  else
    VSA_PYMESHLAB_PLUGIN=$work/build/filter_vsa/meshlab-2025.07d/libfilter_vsa.so VSA_RESOURCES=$root/resources \
      VSA_SOURCE_DIR=$root PYTHONDONTWRITEBYTECODE=1 QT_QPA_PLATFORM=offscreen \
      "$root/.venv/bin/python" -m pytest -p no:cacheprovider -q "$root/tests/pymeshlab/test_vsa_filter.py" \
      >> "$out" 2>&1
    if grep -q "^FAILED .*$expected" "$out"; then
      echo "ok   $name: $(grep -c '^FAILED' "$out") failed, among them $expected"
    else
      echo "BAD  $name: $expected did not fail (see $out)"; failures=$((failures + 1))
    fi
  fi
  cp "$root/$2" "$file"
}

fp=filter_vsa/filter_vsa_fp.cpp
run=filter_vsa/vsa_run.cpp
params=filter_vsa/vsa_parameters.cpp
mutate input-shown $fp "    md.setVisible(input->id(), false);" "" test_the_output_is_shown_alone
mutate name-chained $run ".completeBaseName().remove(ourSuffix);" ".completeBaseName();" \
  test_the_output_is_shown_alone_and_named_after_the_source
mutate seed-ignored $params 'uint64_t(parameters.getInt("RandomSeed"))' "0" test_same_seed_same_output
mutate energy-as-text $run 'f["energy"] = p.energy;' 'f["energy"] = QString::number(p.energy);' \
  test_the_figures_and_their_python_types
mutate no-quality $run "mesh.face[f].Q() = CMeshO::ScalarType(faceRegion[f]);" "mesh.face[f].Q() = 0;" \
  test_every_metric_and_initialization
mutate colours-shared $run "Scatter(std::max(regionCount, 1), region," "Scatter(std::max(regionCount, 1), region / 2," \
  test_every_metric_and_initialization
mutate output-not-current $fp "    md.setCurrent(output);" "" test_every_metric_and_initialization
mutate anchors-shifted $run "for (int v = 0; v < r.meshing.anchors; ++v)" "for (int v = 1; v < r.meshing.anchors; ++v)" \
  test_anchor_layer_and_no_colouring
mutate polygonal-ignored $params 'core.meshing.polygonal = parameters.getBool("Polygonal");' \
  "core.meshing.polygonal = false;" test_polygonal_output_marks_one_polygon_per_region
mutate our-message-lost $fp "if (!outcome.ok) throw MLException(outcome.error);" \
  'if (!outcome.ok) throw MLException("The filter failed.");' "test_bad_input_raises_our_message_and_changes_nothing\[NaN"
mutate input-changed-on-failure $fp "if (!outcome.ok) throw MLException(outcome.error);" \
  "if (!outcome.ok) { md.setVisible(input->id(), false); throw MLException(outcome.error); }" \
  "test_bad_input_raises_our_message_and_changes_nothing\[proxynum 0"
mutate faces-precondition $fp "QAction *) const { return MeshModel::MM_NONE; }" \
  "QAction *) const { return MeshModel::MM_FACENUMBER; }" \
  "test_bad_input_raises_our_message_and_changes_nothing\[point cloud"
mutate not-polygonal-layer $fp "output->updateDataMask(MeshModel::MM_POLYGONAL);" "" \
  test_polygonal_output_marks_one_polygon_per_region
mutate white-output $fp "    output->clearDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY);" "" \
  test_every_metric_and_initialization
[ $failures -eq 0 ] && echo "all mutations detected" || echo "$failures mutation(s) not detected"
exit $failures
