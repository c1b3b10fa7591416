#!/usr/bin/env bash
# Copies the seed corpus for the read_exr target from shared/exr-images (beside
# the repository; override with EXR_IMAGES=dir), else from the few images shipped
# in tests/images, into fuzz/corpus/read_exr, or into the directory given as the
# first argument.
# The corpus is not committed; only crash reproducers are (tests/fuzz-regressions/).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
images="${EXR_IMAGES:-$here/../../shared/exr-images}"
if [ -z "${EXR_IMAGES:-}" ] && [ ! -d "$images" ]; then
    images="$here/../tests/images"
fi
out="${1:-$here/corpus/read_exr}"
mkdir -p "$out"
for p in ScanLines DisplayWindow TestImages Beachball/singlepart.0001.exr v2/LowResLeftView Damaged; do
    [ -e "$images/$p" ] || continue
    # Flattened names (ScanLines_Desk.exr); Damaged/ files have no extension.
    find "$images/$p" -type f ! -name '*.rst' | while read -r f; do
        install -m 644 "$f" "$out/$(echo "${f#"$images"/}" | tr / _)"
    done
done
echo "seeded $(ls "$out" | wc -l) files into $out"
