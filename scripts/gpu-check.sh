#!/usr/bin/env bash
# Cross-driver check (issue 19; docs/performance.md, "GPU check (scripts/gpu-check.sh)"): every
# registered technique's data AOV (the stage's output: visibility, ao, indirect, arealight,
# transparency; a post technique's own AOV, e.g. bloom) on its showcase scene, rendered through two GL contexts — by default EGL (on a
# machine with an NVIDIA GPU and glvnd, the GPU) and OSMesa (Mesa's llvmpipe) — and compared with
# `rtlab compare --over`, against the per-technique tolerances of scripts/gpu-check-tolerances.tsv.
# Prints a table (technique, AOV, RMSE, max, fraction of pixels over the pixel threshold,
# pass/fail) and exits 1 when a technique fails or has no tolerance, 2 on a usage error.
#
#   scripts/gpu-check.sh [options]
#     --rtlab PATH        the binary (default build/rtlab)
#     --size WxH          frame size (default 640x360)
#     --out DIR           keep the images and the table there (default: a temporary folder)
#     --techniques A,B    only these (default: every technique `rtlab list --json` lists)
#     --tolerances FILE   default scripts/gpu-check-tolerances.tsv
#     --set KEY=VALUE     a parameter for every render (repeatable; e.g. msm.centred=true)
#     --self-test         EGL and OSMesa may both be llvmpipe (no GPU needed): checks the script,
#                         the two platforms and the tolerances' format here
#     --render-only B DIR render the set through backend B (egl|osmesa) into DIR and stop
#     --compare A B       compare two folders made by --render-only (A: the GPU's, B: llvmpipe's);
#                         the way to use a GPU machine without Mesa (render there, compare here)
#     --timings DIR       per-pass times instead of the comparison: every technique on its showcase
#                         scene, full frame (color), through --backend (default egl), at --size
#                         (default 1920x1080 in this mode), --frames measured frames (default 20, after 2
#                         warm-up frames), GL timer queries on a GPU (cpu-finish on llvmpipe); writes
#                         DIR/<technique>.json and prints DIR/timings.md (median ms per pass)
#     --render-tests BIN [DIR]  run the render-test binary BIN (build/tests/rtlab_render_tests) on
#                         --backend (default egl), gtest's XML report in DIR (default the --out folder);
#                         prints the renderer, the counts and each failed test; exit 1 on a failure
#     --filter PATTERN    only these render tests (gtest's --gtest_filter syntax)
#     --backend B         the context of --timings and --render-tests: egl (default) or osmesa
#     --frames N          measured frames of --timings (default 20)
set -euo pipefail
cd "$(dirname "$0")/.."

rtlab=build/rtlab
size=640x360
out=""
only=""
tolerances=scripts/gpu-check-tolerances.tsv
self_test=0
render_only=""
render_dir=""
compare_a=""
compare_b=""
timings_dir=""
tests_bin=""
tests_dir=""
filter="*"
backend=egl
frames=20
size_given=0
sets=()
usage() { echo "gpu-check: $1 (see the header of scripts/gpu-check.sh)" >&2; exit 2; }
while [[ $# -gt 0 ]]; do
  case $1 in
    --rtlab) rtlab=${2:?}; shift 2 ;;
    --size) size=${2:?}; size_given=1; shift 2 ;;
    --out) out=${2:?}; shift 2 ;;
    --techniques) only=${2:?}; shift 2 ;;
    --tolerances) tolerances=${2:?}; shift 2 ;;
    --set) sets+=(--set "${2:?}"); shift 2 ;;
    --self-test) self_test=1; shift ;;
    --render-only) render_only=${2:?}; render_dir=${3:?}; shift 3 ;;
    --compare) compare_a=${2:?}; compare_b=${3:?}; shift 3 ;;
    --timings) timings_dir=${2:?}; shift 2 ;;
    --render-tests)
      tests_bin=${2:?}; shift 2
      if [[ $# -gt 0 && $1 != --* ]]; then tests_dir=$1; shift; fi ;;
    --filter) filter=${2:?}; shift 2 ;;
    --backend) backend=${2:?}; shift 2 ;;
    --frames) frames=${2:?}; shift 2 ;;
    *) usage "unknown option '$1'" ;;
  esac
done
[[ $backend == egl || $backend == osmesa ]] || usage "--backend must be egl or osmesa"
[[ $frames =~ ^[1-9][0-9]*$ ]] || usage "--frames must be a positive integer"
[[ -n $timings_dir && $size_given == 0 ]] && size=1920x1080
[[ -f $tolerances ]] || usage "no tolerance file $tolerances"
[[ $size =~ ^[0-9]+x[0-9]+$ ]] || usage "--size must be WxH"
# Debian's python3, as the bench scripts (the python3 first on PATH may be another); elsewhere (a GPU
# machine's image) the one on PATH: the script needs only json and xml.
py=/usr/bin/python3
[[ -x $py ]] || py=$(command -v python3 || true)
[[ -n $py ]] || usage "python3 is needed"
work=${out:-$(mktemp -d)}
mkdir -p "$work"

[[ -x $rtlab ]] || usage "no rtlab binary at $rtlab (cmake --build build --target rtlab)"

# --render-tests: the render tests on one backend (on a GPU machine: the GPU through EGL). The
# binary finds its data through RTLAB_DATA_DIR (this checkout) and writes its scratch files into
# its build folder's test_tmp, created here when the binary was copied without it.
if [[ -n $tests_bin ]]; then
  [[ -x $tests_bin ]] || usage "no render-test binary at $tests_bin"
  dir=${tests_dir:-$work}
  mkdir -p "$dir"
  status=0
  rm -f "$dir/render_tests.xml" # a report left by an earlier run must not stand for this one
  RTLAB_DATA_DIR=${RTLAB_DATA_DIR:-$PWD} RTLAB_TEST_BACKEND=$backend "$tests_bin" \
    --gtest_filter="$filter" --gtest_output="xml:$dir/render_tests.xml" >"$dir/render_tests.log" 2>&1 || status=$?
  # The renderer's name, from one tiny frame of the rtlab binary on the same backend.
  renderer="unknown renderer (no $rtlab)"
  if [[ -x $rtlab ]] && "$rtlab" render --backend "$backend" --size 8x8 --out "$dir/renderer.exr" \
      --stats "$dir/renderer.json" 2>/dev/null; then
    renderer=$("$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["renderer"])' "$dir/renderer.json")
  fi
  "$py" - "$dir/render_tests.xml" "$dir/render_tests.log" "$backend" "$renderer" <<'PYEOF' || exit 1
import sys, xml.etree.ElementTree as ET
xml_file, log, backend, renderer = sys.argv[1:]
try:
    root = ET.parse(xml_file).getroot()
except (OSError, ET.ParseError) as e:
    print("gpu-check: the render tests wrote no report (%s); the end of %s:" % (e, log))
    print("".join(open(log, errors="replace").readlines()[-30:]))
    sys.exit(1)
failed = [c.get("classname") + "." + c.get("name") for c in root.iter("testcase") if c.find("failure") is not None]
print("gpu-check: render tests on %s (%s): %s tests, %d failed, %s s" % (
    backend, renderer, root.get("tests"), len(failed), root.get("time")))
for f in failed: print("  FAILED " + f)
sys.exit(1 if failed else 0)
PYEOF
  [[ $status == 0 ]] || { echo "gpu-check: the render-test binary exited with $status (log: $dir/render_tests.log)" >&2; exit 1; }
  exit 0
fi

# technique <TAB> stage <TAB> data AOV <TAB> scene, one line each, from the registry.
list_jobs() {
  "$rtlab" list --json | "$py" -c '
import json, sys
only = [t for t in sys.argv[1].split(",") if t]
d = json.load(sys.stdin)
aov = {s["id"]: (s["aov"] or {}).get("name") for s in d["stages"]}
known = {t["id"] for t in d["techniques"]}
for t in only:
    if t not in known: sys.exit("gpu-check: unknown technique %r (rtlab list)" % t)
for t in d["techniques"]:
    if only and t["id"] not in only: continue
    name = aov.get(t["stage"]) or (t["id"] if t["id"] in t["aovs"] else "color")
    print("\t".join([t["id"], t["stage"], name, t["showcase_scene"]]))
' "$only"
}

# Renders every job through backend $1 into folder $2 (<technique>.json and the image): with $3 =
# data, its data AOV (<technique>.exr); with $3 = timings, its whole frame over $frames frames
# (<technique>.png).
render_set() {
  local backend=$1 dir=$2 mode=$3 what
  mkdir -p "$dir"
  while IFS=$'\t' read -r id stage aov scene; do
    if [[ $mode == data ]]; then what=(--aov "$aov" --out "$dir/$id.exr"); else what=(--frames "$frames" --out "$dir/$id.png"); fi
    "$rtlab" render --backend "$backend" --scene "$scene" -t "$id" --size "$size" "${what[@]}" \
      --stats "$dir/$id.json" "${sets[@]}" 2>"$dir/$id.log" ||
      { echo "gpu-check: $id failed to render through $backend:" >&2; cat "$dir/$id.log" >&2; return 1; }
  done < "$work/jobs.tsv"
}

renderer_of() { "$py" -c 'import json,sys; print(json.load(open(sys.argv[1]))["renderer"])' "$1"; }
size_of() { "$py" -c 'import json,sys; print("%dx%d" % tuple(json.load(open(sys.argv[1]))["size"]))' "$1"; }

list_jobs > "$work/jobs.tsv"
[[ -s $work/jobs.tsv ]] || usage "no technique to check"

# --timings: each technique's whole frame on its showcase scene; the table lists every pass's median.
if [[ -n $timings_dir ]]; then
  render_set "$backend" "$timings_dir" timings
  "$py" - "$work/jobs.tsv" "$timings_dir" <<'PYEOF'
import json, sys
jobs, folder = sys.argv[1:]
lines, head = [], None
for line in open(jobs):
    tid, stage, aov, scene = line.rstrip("\n").split("\t")
    s = json.load(open("%s/%s.json" % (folder, tid)))
    head = head or "%s, %s, %dx%d, %d frames, timing %s" % (s["renderer"], s["backend"], s["size"][0], s["size"][1], s["frames"], s["timing"])
    own = ", ".join("%s %.3f" % (p["name"], p["ms"]) for p in s["passes"] if p["technique"] == tid)
    frame = ", ".join("%s %.3f" % (p["name"], p["ms"]) for p in s["passes"] if p["technique"] == "")
    lines.append("| %s | %s | %s | %s | %.3f | %d |" % (tid, scene, own or "-", frame, s["frame_ms"], s["gl_errors"]))
with open("%s/timings.md" % folder, "w") as t:
    t.write("%s; median ms per pass\n\n" % head)
    t.write("| technique | scene | its passes | framework passes | frame | GL errors |\n|---|---|---|---|---:|---:|\n")
    t.write("\n".join(lines) + "\n")
print(open("%s/timings.md" % folder).read(), end="")
PYEOF
  exit 0
fi

if [[ -n $render_only ]]; then
  render_set "$render_only" "$render_dir" data
  echo "gpu-check: rendered $(wc -l < "$work/jobs.tsv") techniques through $render_only ($(renderer_of "$render_dir/$(head -1 "$work/jobs.tsv" | cut -f1).json")) into $render_dir"
  exit 0
fi

if [[ -n $compare_a ]]; then
  gpu=$compare_a ref=$compare_b
else
  gpu=$work/egl ref=$work/osmesa
  render_set egl "$gpu" data
  render_set osmesa "$ref" data
fi
first=$(head -1 "$work/jobs.tsv" | cut -f1)
gpu_renderer=$(renderer_of "$gpu/$first.json")
ref_renderer=$(renderer_of "$ref/$first.json")
echo "gpu-check: A = $gpu_renderer, B = $ref_renderer, $(size_of "$gpu/$first.json")"
if [[ $self_test == 0 && $gpu_renderer == *llvmpipe* ]]; then
  echo "gpu-check: side A rendered on llvmpipe, not a GPU (EGL found Mesa: see docs/performance.md, \"GPU check (scripts/gpu-check.sh)\"; --self-test to accept)" >&2
  exit 1
fi

# The table: each technique's compare against its tolerances.
"$py" - "$work/jobs.tsv" "$tolerances" "$gpu" "$ref" "$rtlab" "$work/table.md" <<'PYEOF'
import json, subprocess, sys
jobs, tolerance_file, gpu, ref, rtlab, table = sys.argv[1:]
tolerances = {}
for n, line in enumerate(open(tolerance_file), 1):
    line = line.split("#", 1)[0].strip()
    if not line: continue
    f = line.split()
    if len(f) != 4: sys.exit("gpu-check: %s:%d: expected: technique rmse pixel fraction" % (tolerance_file, n))
    tolerances[f[0]] = tuple(float(x) for x in f[1:])
rows, failed = [], 0
for line in open(jobs):
    tid, stage, aov, scene = line.rstrip("\n").split("\t")
    tol = tolerances.get(tid)
    if tol is None:
        rows.append((tid, aov, scene, "-", "-", "-", "FAIL: no tolerance in " + tolerance_file)); failed += 1; continue
    rmse_max, pixel, fraction_max = tol
    run = subprocess.run([rtlab, "compare", "%s/%s.exr" % (gpu, tid), "%s/%s.exr" % (ref, tid), "--json",
                          "--over", repr(pixel)], capture_output=True, text=True)
    if run.returncode != 0:  # a missing image, or two sizes
        rows.append((tid, aov, scene, "-", "-", "-", "FAIL: " + run.stderr.strip())); failed += 1; continue
    m = json.loads(run.stdout)
    rmse, mx, frac = m["rmse"], m["max_abs"], m["over"]["fraction"]
    ok = rmse is not None and rmse <= rmse_max and frac <= fraction_max and m["nan_count"] == 0
    failed += not ok
    verdict = "pass" if ok else "FAIL (rmse <= %g, fraction over %g <= %g%s)" % (
        rmse_max, pixel, fraction_max, "" if m["nan_count"] == 0 else ", NaN")
    rows.append((tid, aov, scene, "%.5f" % rmse, "%.4f" % mx, "%.5f (> %g)" % (frac, pixel), verdict))
with open(table, "w") as t:
    t.write("| technique | AOV | scene | RMSE | max | fraction over | result |\n|---|---|---|---:|---:|---:|---|\n")
    for r in rows: t.write("| " + " | ".join(r) + " |\n")
print(open(table).read(), end="")
print("gpu-check: %d of %d techniques failed" % (failed, len(rows)))
sys.exit(1 if failed else 0)
PYEOF
