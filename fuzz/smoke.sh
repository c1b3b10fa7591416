#!/usr/bin/env bash
# CI smoke test: fuzzes each target (read_exr, run_job, then read_foreign) for
# ~25 s (FUZZ_SECONDS to change), about a minute and a half in all.
# Exits 0 with a message when cargo-fuzz or a toolchain able to build the targets
# is missing; non-zero when the targets do not compile (cargo check) or the
# fuzzer itself finds a crash, timeout or OOM.
set -uo pipefail
cd "$(dirname "$0")"
seconds="${FUZZ_SECONDS:-25}"
# cargo-fuzz passes nightly-only flags (-Zsanitizer=address); this lets stable accept them.
export RUSTC_BOOTSTRAP=1

if ! cargo fuzz --version >/dev/null 2>&1; then
    if [ -n "${CI:-}" ]; then
        cargo install cargo-fuzz --locked || { echo "fuzz smoke: SKIPPED (cannot install cargo-fuzz)"; exit 0; }
    else
        echo "fuzz smoke: SKIPPED (cargo-fuzz not installed: cargo install cargo-fuzz --locked)"
        exit 0
    fi
fi

# Both targets in one build.
if ! cargo fuzz build; then
    # Our own code not compiling (a moved module) is a failure, not a toolchain's limit.
    if ! cargo check --bins; then
        echo "fuzz smoke: FAILED (the fuzz targets do not compile)"
        exit 1
    fi
    echo "fuzz smoke: SKIPPED (this toolchain cannot build the fuzz targets)"
    exit 0
fi

# A fresh corpus of the seeds only: a grown local corpus takes minutes to load.
corpus="$(mktemp -d)"
trap 'rm -rf "$corpus"' EXIT
./seed.sh "$corpus" || echo "fuzz smoke: no seed images, starting from an empty corpus"
# Small seeds only, so that loading them takes seconds and leaves time to mutate.
find "$corpus" -type f -size +256k -delete

failed=0
for target in read_exr run_job read_foreign; do
    # Each target grows its own copy of the seeds.
    work="$corpus/$target"
    mkdir "$work"
    find "$corpus" -maxdepth 1 -type f -exec cp {} "$work" \;
    if cargo fuzz run "$target" "$work" -- -max_total_time="$seconds" \
            -rss_limit_mb=2048 -timeout=10 -max_len=300000; then
        echo "fuzz smoke: $target OK (${seconds} s, no crash)"
    else
        echo "fuzz smoke: $target FAILED: reproducer in fuzz/artifacts/$target/" >&2
        failed=1
    fi
done
exit "$failed"
