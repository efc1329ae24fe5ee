#!/usr/bin/env bash
# Run the FreeCAD tests of the TemplateQuad add-on; exit non-zero on any failure.
#
#   tests/freecad/run_freecad_tests.sh [TQUAD_MODULE_DIR]   (default <repo>/build/python/tquad)
#
# 1. install.sh installs the add-on (with the tquad module) into a temporary
#    FREECAD_USER_HOME, so the tests see it exactly as a user's FreeCAD would;
# 2. test_headless.py, test_fem_plate.py, test_fem_solid.py and test_u_channel.py run in
#    freecadcmd, one process each;
# 3. test_gui.py runs in the FreeCAD GUI under Xvfb (when freecad and xvfb-run exist)
#    and saves a screenshot to $TQ_SCREENSHOT (default <repo>/docs/freecad_screenshot.png).
# The last line is the summary "N passed, M failed" (plus skips). Without freecadcmd
# everything is skipped and the exit status is 0.
set -uo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
module="${1:-$repo/build/python/tquad}"
screenshot="${TQ_SCREENSHOT:-$repo/docs/freecad_screenshot.png}"

if ! command -v freecadcmd >/dev/null 2>&1; then
  echo "skipped: freecadcmd not installed"
  exit 0
fi

mkdir -p "${TQ_SCREENSHOT_DIR:-$repo/docs}" "$(dirname "$screenshot")"
home=$(mktemp -d "${TMPDIR:-/tmp}/tq_freecad_home.XXXXXX")
trap 'rm -rf "$home"' EXIT

if ! FREECAD_USER_HOME="$home" bash "$repo/freecad_workbench/install.sh" "$module" \
     >"$home/install.log" 2>&1; then
  cat "$home/install.log"
  echo "0 passed, 1 failed (install.sh failed)"
  exit 1
fi

passed=0 failed=0 skipped=0 notes=()

# tally LABEL RESULT_FILE EXIT_STATUS: add a run's counts. A run that crashed, or that
# exited non-zero without a failing test, counts as one failure: it never passes silently.
tally() {
  local label="$1" file="$2" status="$3" counts
  if [[ ! -s "$file" ]]; then
    failed=$((failed + 1)); notes+=("$label: no result (exit status $status)")
    return
  fi
  counts=$(/usr/bin/python3 -c 'import json,sys; t=json.load(open(sys.argv[1])); print(t["passed"], t["failed"], t["skipped"])' "$file")
  read -r p f s <<<"$counts"
  passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + s))
  if [[ "$status" -ne 0 && "$f" -eq 0 ]]; then
    failed=$((failed + 1)); notes+=("$label: exit status $status")
  fi
}

common_env=(FREECAD_USER_HOME="$home" TQ_TEST_DIR="$here" TQ_CLI="${TQ_CLI:-$repo/build/bin/tquad}")

for test_module in test_headless test_fem_plate test_fem_solid test_u_channel; do
  echo "=== $test_module (freecadcmd) ==="
  result="$home/$test_module.json"
  env "${common_env[@]}" TQ_TEST_MODULES="$test_module" TQ_RESULT_FILE="$result" \
      TQ_RUNNER_MAIN=1 timeout 300 \
      freecadcmd -c "exec(open('$here/freecad_test_runner.py').read())"
  tally "$test_module" "$result" $?
done

if command -v freecad >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1; then
  echo "=== test_gui (FreeCAD GUI under Xvfb) ==="
  result="$home/test_gui.json"
  env "${common_env[@]}" TQ_RESULT_FILE="$result" TQ_SCREENSHOT="$screenshot" \
      TQ_SCREENSHOT_DIR="${TQ_SCREENSHOT_DIR:-$repo/docs}" QTWEBENGINE_DISABLE_SANDBOX=1 timeout 300 \
      xvfb-run -a -s "-screen 0 1280x1024x24" freecad "$here/gui_test_macro.py"
  tally test_gui "$result" $?
else
  echo "skipped: GUI test (needs freecad and xvfb-run)"
  skipped=$((skipped + 1))
fi

for note in "${notes[@]+"${notes[@]}"}"; do echo "note: $note"; done
echo "$passed passed, $failed failed, $skipped skipped"
[[ "$failed" -eq 0 ]]
