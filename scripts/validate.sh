#!/usr/bin/env bash
# Regenerates every validation report (validation/<case>/) into out/validation/<case>/ and checks the
# acceptance bands: exit status 0 when all hold. Installs and builds first, like the quick start.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
bash "$root/scripts/build.sh" >/dev/null
"${KERF_BUILD_DIR:-$root/build}/validation/run_validation" all "$root/out/validation"
