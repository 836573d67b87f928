#!/usr/bin/env bash
# The GL error total of the last ctest run in BUILD_DIR (docs/testing.md "GL errors"). Each run of
# a GL test binary (rtlab_render_tests, rtlab_cli_tests) writes BUILD_DIR/gl_errors/<binary>-<pid>.txt
# ("gl_errors: N ..." and the error messages; the ctest fixture gl_errors_reset empties the folder
# first); ctest's BUILD_DIR/Testing/Temporary/LastTest.log names the runs. Prints
# "GL errors in the suite: N" and the reports that have errors. Exit 0 when N is 0 and every run
# wrote its report, 1 otherwise (one line on stderr per run without a report), 2 on a usage error.
#   bash scripts/gl_error_total.sh BUILD_DIR
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "gl_error_total: error: usage: gl_error_total.sh BUILD_DIR" >&2
  exit 2
fi
dir=$1
log=$dir/Testing/Temporary/LastTest.log
reports=$dir/gl_errors
if [[ ! -f $log ]]; then
  echo "gl_error_total: error: no $log (run ctest in $dir first)" >&2
  exit 2
fi

status=0
for binary in rtlab_render_tests rtlab_cli_tests; do
  ran=$(grep -c "^Command: \"[^\"]*/$binary\"" "$log" || true)
  wrote=$(find "$reports" -maxdepth 1 -name "$binary-*.txt" 2>/dev/null | wc -l)
  if ((wrote < ran)); then
    echo "gl_error_total: $((ran - wrote)) of the $ran runs of $binary wrote no GL error report in $reports/" >&2
    status=1
  fi
done

total=0
if [[ -d $reports ]]; then
  while IFS= read -r -d '' report; do
    n=$(awk '/^gl_errors: /{s += $2} END {print s + 0}' "$report")
    if ((n > 0)); then
      echo "$report:"
      cat "$report"
    fi
    total=$((total + n))
  done < <(find "$reports" -maxdepth 1 -name '*.txt' -print0 | sort -z)
fi
echo "GL errors in the suite: $total"
((total == 0)) || status=1
exit $status
