#!/usr/bin/env bash
# Grades every student folder of a class in one go (docs/exercises.md "Grading a class"):
#   bash scripts/grade_class.sh CLASS_DIR OUT_DIR [--jobs N] [--rtlab BIN] [-- GRADE_OPTIONS...]
# CLASS_DIR holds one folder per student (each made by `rtlab exercise new`). For each it runs
# `rtlab exercise grade FOLDER --json --report OUT_DIR/reports/NAME [GRADE_OPTIONS]`, N at a time
# (default 1: the grader's workers use every core already), and writes
#   OUT_DIR/json/NAME.json      the grade (docs/contract.md "Exercises")
#   OUT_DIR/reports/NAME/       the report pages
#   OUT_DIR/grades.csv          student,exercise,score,passed,views_passed,views,status
# status: graded | compile_error (exit 5; the JSON is still there) | not_an_exercise (exit 3) |
# error (any other exit; its message is in OUT_DIR/json/NAME.err). OUT_DIR must not exist or be
# empty. Exit 0 when every folder was graded (passed or not), 1 when some could not be.
set -euo pipefail
usage() { echo "usage: bash scripts/grade_class.sh CLASS_DIR OUT_DIR [--jobs N] [--rtlab BIN] [-- GRADE_OPTIONS...]" >&2; exit 2; }
[[ $# -ge 2 ]] || usage
class=$1 out=$2
shift 2
jobs=1
rtlab=$(command -v rtlab || true)
[[ -z $rtlab && -x "$(dirname "$0")/../build/rtlab" ]] && rtlab="$(dirname "$0")/../build/rtlab"
extra=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --jobs) [[ $# -ge 2 && $2 =~ ^[1-9][0-9]*$ ]] || { echo "grade_class: error: --jobs needs a positive integer" >&2; exit 2; }; jobs=$2; shift 2 ;;
    --rtlab) [[ $# -ge 2 ]] || usage; rtlab=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) echo "grade_class: error: unknown option '$1'" >&2; usage ;;
  esac
done
[[ -d $class ]] || { echo "grade_class: error: '$class' is not a directory" >&2; exit 3; }
[[ -n $rtlab && -x $rtlab ]] || { echo "grade_class: error: no rtlab binary (put it on PATH or pass --rtlab BIN)" >&2; exit 3; }
if [[ -e $out && ! ( -d $out && -z "$(ls -A "$out")" ) ]]; then
  echo "grade_class: error: '$out' exists and is not an empty directory" >&2; exit 6
fi
mkdir -p "$out/json" "$out/reports"
rtlab=$(realpath "$rtlab")

mapfile -t students < <(find "$class" -mindepth 1 -maxdepth 1 -type d -printf '%f\n' | LC_ALL=C sort)
[[ ${#students[@]} -gt 0 ]] || { echo "grade_class: error: '$class' holds no student folders" >&2; exit 3; }
echo "grade_class: ${#students[@]} folders, $jobs at a time" >&2

grade_one() { # name: runs the grade, records the exit code next to the JSON
  local name=$1 rc=0
  "$rtlab" exercise grade "$class/$name" --json --report "$out/reports/$name" "${extra[@]}" \
    >"$out/json/$name.json" 2>"$out/json/$name.err" || rc=$?
  echo "$rc" >"$out/json/$name.rc"
  echo "grade_class: $name (exit $rc)" >&2
}
export -f grade_one
export rtlab class out
export GRADE_EXTRA="${extra[*]:-}"
start=$(date +%s.%N)
if [[ $jobs -eq 1 ]]; then
  for s in "${students[@]}"; do grade_one "$s"; done
else
  printf '%s\0' "${students[@]}" | xargs -0 -n 1 -P "$jobs" bash -c 'extra=($GRADE_EXTRA); grade_one "$1"' _
fi
end=$(date +%s.%N)

/usr/bin/python3 - "$out" "$start" "$end" "${students[@]}" <<'PY'
import csv, json, os, sys
out, start, end, students = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4:]
rows, failed = [], 0
for name in students:
    rc = int(open(os.path.join(out, "json", name + ".rc")).read())
    row = {"student": name, "exercise": "", "score": "", "passed": "", "views_passed": "", "views": "",
           "status": {0: "graded", 5: "compile_error", 3: "not_an_exercise"}.get(rc, "error")}
    if rc in (0, 5):
        g = json.load(open(os.path.join(out, "json", name + ".json")))
        row.update(exercise=g["exercise"], score=g["score"], passed=str(g["passed"]).lower(),
                   views_passed=sum(1 for v in g["views"] if v["passed"]), views=len(g["views"]))
    else:
        failed += 1
    rows.append(row)
with open(os.path.join(out, "grades.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)
print("grade_class: %d folders in %.1f s (%.2f s each); %s" % (len(rows), end - start, (end - start) / len(rows),
      os.path.join(out, "grades.csv")), file=sys.stderr)
sys.exit(1 if failed else 0)
PY
