#!/usr/bin/env bash
# The layout rules, checked in CI (scripts/test.sh): the folders' #include "..." graph has no
# circle; the engine's wings include no other wing (below); the parts (profiles/, detachment/, controllers/, friction/) include nothing of engine/ but its
# vocabulary, engine/base/; nothing below the outputs includes engine/output/; only tests and
# bench include engine/reference/; nothing but apps/ includes apps/; bench/ includes no tests/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

status=0
# refuse MESSAGE LINES: prints the message and the offending include lines when there are any.
refuse() {
  if [ -n "$2" ]; then
    echo "check_includes: $1" >&2
    echo "$2" >&2
    status=1
  fi
}
includes() { grep -rnE '^#include "' "$@" --include='*.hpp' --include='*.cpp' --include='*.h' || true; }

refuse "the parts may include only engine/base/ of engine/:" \
  "$(includes profiles detachment controllers friction | grep '#include "engine/' | grep -v '#include "engine/base/' || true)"
refuse "apps/ may not include engine/reference/ (tests and bench only):" \
  "$(includes apps | grep '#include "engine/reference/' || true)"
refuse "only the command (apps/) includes apps/; engine/ and python/ may not:" \
  "$(includes engine python | grep '#include "apps/' || true)"
refuse "bench/ may not include tests/ (the shared oracles live in engine/reference/):" \
  "$(includes bench | grep '#include "tests/' || true)"
refuse "the outputs sit above the engine: engine/ includes engine/output/ only from output/ itself:" \
  "$(includes engine | grep '#include "engine/output/' | grep -v '^engine/output/' || true)"

# The engine's wings: pull_off/ (the shorthand's row), program/ (a program's row) and continuum/
# (the branch with no springs) are three engines side by side; none includes another, nor the
# accuracy drivers above them (accuracy/) or the entry (run/). accuracy/ may take any wing, not
# run/; the folders below the wings (base, scene, model, events, result, and measured, the
# readers of measured force curves) include none of them.
wings=(pull_off program continuum)
for wing in "${wings[@]}"; do
  others="$(printf '%s\n' "${wings[@]}" accuracy run | grep -vx "$wing" | paste -sd'|')"
  refuse "engine/$wing/ is a wing: it may not include another wing, accuracy/ or run/:" \
    "$(includes "engine/$wing" | grep -E "#include \"engine/($others)/" || true)"
done
refuse "engine/accuracy/ sits above the wings and below the entry: it may not include run/:" \
  "$(includes engine/accuracy | grep '#include "engine/run/' || true)"
refuse "the folders below the wings (base, scene, model, events, result, measured) may not include a wing, accuracy/ or run/:" \
  "$(includes engine/base engine/scene engine/model engine/events engine/result engine/measured |
     grep -E '#include "engine/(pull_off|program|continuum|accuracy|run)/' || true)"

# The folder graph: each engine/ subfolder a node, and apps, python/src, controllers, detachment,
# profiles, friction; an edge for every #include "..." from one node into another. A circle is refused
# with the include lines that make each of its edges.
nodes=(engine/*/ apps/ python/src/ controllers/ detachment/ profiles/ friction/)
cycles="$(includes "${nodes[@]%/}" | awk '
  function node(path,   parts) {
    split(path, parts, "/")
    if (parts[1] == "engine" || parts[1] == "python") return parts[1] "/" parts[2]
    return parts[1]
  }
  function visit(u,   i, v) {
    color[u] = 1
    stack[++depth] = u
    for (i = 1; i <= degree[u]; i++) {
      v = next_of[u, i]
      if (color[v] == 1) report(v)
      else if (color[v] == 0) visit(v)
    }
    depth--
    color[u] = 2
  }
  function report(v,   i, start, line) {
    for (start = depth; stack[start] != v; start--) {}
    line = ""
    for (i = start; i <= depth; i++) line = line stack[i] " -> "
    print "circle: " line v
    for (i = start; i <= depth; i++) {
      edge = stack[i] SUBSEP (i < depth ? stack[i + 1] : v)
      print edge_lines[edge]
      if (edge_count[edge] > 3) print "  (and " edge_count[edge] - 3 " more)"
    }
  }
  {
    file = $0; sub(/:.*/, "", file)
    target = $0; sub(/^[^"]*"/, "", target); sub(/".*/, "", target)
    from = node(file); to = node(target)
    if (from == to || !(to ~ /^(engine\/[^\/]+|apps|python\/src|controllers|detachment|profiles|friction)$/)) next
    # Each edge keeps its first three include lines to show, and how many it has.
    if (!((from, to) in edge_lines)) {
      next_of[from, ++degree[from]] = to
      order[++nodes] = from
      edge_lines[from, to] = "  " $0
    } else if (edge_count[from, to] < 3) {
      edge_lines[from, to] = edge_lines[from, to] "\n  " $0
    }
    edge_count[from, to]++
  }
  END { for (n = 1; n <= nodes; n++) if (color[order[n]] == 0) visit(order[n]) }
')"
refuse "the folder include graph has a circle (a folder may not include one that includes it back):" \
  "$cycles"

[ "$status" -eq 0 ] && echo "check_includes: no folder circle; no wing includes another; parts include only engine/base/; outputs above the engine; engine/reference/ for tests and bench; apps/ for itself; bench/ no tests/"
exit "$status"
