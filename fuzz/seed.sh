#!/usr/bin/env bash
# Copies the seed corpus into fuzz/corpus/read_exr and fuzz/corpus/run_job,
# or into the directories given as arguments: the public images of
# shared/exr-images (beside the repository; override with EXR_IMAGES=dir; else
# the few images shipped in tests/images),
# including its Damaged/ files, the small files of seeds/ (ZIP, ZIPS, PIZ and
# a deep ZIPS crop, to reach the engine's paths quickly) and the regression
# inputs of ../tests/fuzz-regressions.
# The corpus is not committed; only crash reproducers are (tests/fuzz-regressions/).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
images="${EXR_IMAGES:-$here/../../shared/exr-images}"
if [ -z "${EXR_IMAGES:-}" ] && [ ! -d "$images" ]; then
    images="$here/../tests/images"
fi
if [ $# -eq 0 ]; then
    set -- "$here/corpus/read_exr" "$here/corpus/run_job"
fi
for out in "$@"; do
    mkdir -p "$out"
    for p in ScanLines DisplayWindow TestImages Beachball/singlepart.0001.exr v2/LowResLeftView Damaged; do
        [ -e "$images/$p" ] || continue
        # Flattened names (ScanLines_Desk.exr); Damaged/ files have no extension.
        find "$images/$p" -type f ! -name '*.rst' | while read -r f; do
            install -m 644 "$f" "$out/$(echo "${f#"$images"/}" | tr / _)"
        done
    done
    for f in "$here"/seeds/* "$here"/../tests/fuzz-regressions/*; do
        case "$f" in *.md) continue ;; esac
        [ -f "$f" ] && install -m 644 "$f" "$out/$(basename "$(dirname "$f")")_$(basename "$f")"
    done
    echo "seeded $(ls "$out" | wc -l) files into $out"
done
