#!/usr/bin/env bash
# The committed data/flows/vortex_street.flow must be exactly what gsv-flow writes (usage: GSV_FLOW), so
# the data cannot drift from its generator.
set -euo pipefail
gsv_flow=$1
root=$(cd "$(dirname "$0")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$gsv_flow" write vortex_street 128 64 16 "$tmp/vortex_street.flow" >/dev/null
if ! cmp "$tmp/vortex_street.flow" "$root/data/flows/vortex_street.flow"; then
  echo "check_flow_data: data/flows/vortex_street.flow differs from its generator; if the change is meant," >&2
  echo "  rebuild it with: gsv-flow write vortex_street 128 64 16 data/flows/vortex_street.flow" >&2
  exit 1
fi
echo "data/flows/vortex_street.flow matches its regeneration"
