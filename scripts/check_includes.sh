#!/usr/bin/env bash
# The layout rule, checked in CI (scripts/test.sh): the parts (profiles/, detachment/,
# controllers/) include nothing of engine/ but its vocabulary, engine/base/; and the mdrsim
# command (apps/) includes nothing of engine/reference/, which tests and bench alone link.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

status=0
parts="$(grep -rnE '#include "engine/' profiles detachment controllers | grep -v '#include "engine/base/' || true)"
if [ -n "$parts" ]; then
  echo "check_includes: the parts may include only engine/base/ of engine/:" >&2
  echo "$parts" >&2
  status=1
fi
command="$(grep -rnE '#include "engine/reference/' apps || true)"
if [ -n "$command" ]; then
  echo "check_includes: apps/ may not include engine/reference/ (tests and bench only):" >&2
  echo "$command" >&2
  status=1
fi
[ "$status" -eq 0 ] && echo "check_includes: the parts include only engine/base/, apps/ no engine/reference/"
exit "$status"
