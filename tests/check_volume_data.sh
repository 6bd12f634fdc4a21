#!/usr/bin/env bash
# The committed data/volumes/anatomical.nii must be byte for byte the file Debian's python3-nibabel ships, so
# data/README.md's note of where it came from stays true. Exit 77 (ctest: skipped) where the package is not
# installed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source_file=/usr/lib/python3/dist-packages/nibabel/tests/data/anatomical.nii
if [ ! -f "$source_file" ]; then
  echo "check_volume_data: $source_file not found (python3-nibabel is not installed); skipped"
  exit 77
fi
if ! cmp "$source_file" "$root/data/volumes/anatomical.nii"; then
  echo "check_volume_data: data/volumes/anatomical.nii differs from python3-nibabel's $source_file;" >&2
  echo "  if the package's file changed on purpose, copy it again and update data/README.md's facts" >&2
  exit 1
fi
echo "data/volumes/anatomical.nii matches $source_file"
