#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fails (and lists the files) when code below the front ends names io::Case or includes
# the front ends' header (issue 43): the case is translated once, into a run plan
# (app/case_translation.cpp), by the front ends: the CLI (app/cli.cpp, app/main.cpp), the
# study command (app/study*.cpp, app/study.hpp) and their entry header
# (app/simulation.hpp); the Python module lives outside src/formflow.
# Usage: scripts/check_case_boundary.sh
set -euo pipefail
cd "$(dirname "$0")/.."
front_ends='^src/formflow/(io/.*|app/(cli|main|study|study_plan|study_command|case_translation)\.cpp|app/(cli|study|simulation)\.hpp)$'
status=0
# The check's own premise: every front end it names exists (a rename would empty it).
for file in app/cli.cpp app/main.cpp app/study.cpp app/study_plan.cpp app/study_command.cpp \
  app/case_translation.cpp app/simulation.hpp; do
  [ -f "src/formflow/$file" ] || { echo "front end src/formflow/$file is missing"; status=1; }
done
offenders=$(grep -rl 'io::Case' src/formflow | grep -Ev "$front_ends" || true)
if [ -n "$offenders" ]; then
  echo "io::Case below the front ends (take the run plan, app/run_plan.hpp):"
  sed 's/^/  /' <<<"$offenders"
  status=1
fi
includers=$(grep -rlE '#include "formflow/(app/simulation|io/case)\.hpp"' src/formflow |
  grep -Ev "$front_ends" || true)
if [ -n "$includers" ]; then
  echo "the case's headers included below the front ends:"
  sed 's/^/  /' <<<"$includers"
  status=1
fi
[ "$status" -eq 0 ] && echo "io::Case only in io/ and the front ends: $(grep -rl 'io::Case' src/formflow | wc -l) files"
exit "$status"
