#!/usr/bin/env bash
# Physics functions name their own fields, never the scene's keys (issue 56 item 3): no source of the analytic
# physics (the flow-stress terms, the force relations of analytic/forces/ but the models' units, the trepanning
# drill's model) writes a key of a scene's `cut`, `tool` or `models` section as a string. The units (forces/*_model,
# forces/chip_term, forces/glass_edge, which builds a scene) and kinds/ name the keys, mapping the physics' fields
# (kinds/scene_keys.hpp). A path given by the caller (validate(path)) is the caller's.
# Usage: bash analytic_physics_names.sh <bin dir (unused)> <source dir>. Needs grep only: no build.
set -uo pipefail
src="$2"
cd "$src/analytic" || exit 1
physics=$(ls flow_stress/*.cpp forces/*.cpp trepanning/trepanning.cpp |
          grep -v -e '_model\.cpp$' -e '^forces/chip_term\.cpp$' -e '^forces/glass_edge\.cpp$')
[ -n "$physics" ] || { echo "FAIL: no physics sources found" >&2; exit 1; }
hits=$(grep -nE '"(cut|tool|models)\.[a-z_]+' $physics)
if [ -n "$hits" ]; then
  echo "FAIL: physics sources name scene keys (name the function's own field; the scene layer maps it):" >&2
  echo "$hits" >&2
  exit 1
fi
echo "analytic physics names: ok ($(echo "$physics" | wc -l) sources)"
