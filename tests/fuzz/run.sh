#!/usr/bin/env bash
# tests/fuzz/run.sh - fuzz SnowWall's input parsers with libFuzzer.
#
# Usage: tests/fuzz/run.sh [--time SECONDS] [--jobs N] [--out DIR] [TARGET...] [--help]
#
# Targets (default: all):
#   config   snowregime's --config reader (swr_params_load, regime/kernel/swr_params.c)
#   coeffs   the wall model's regime.coeffs reader and decisions (sww_regime_load,
#            wallmodel/core/sww_load.c and the other sww_*.c)
#   simcsv   snowphoto's simulated-map CSV reader (swi_simmap_read_mem)
#   image    snowphoto's PNG and JPEG readers (swi_image_read_mem; Debian's libpng
#            and libjpeg, not instrumented; built with limits of 4000 px per side
#            and 4 MP instead of 30000 and 100 MP, so in-limit images stay fast)
# Each target is built with Debian's clang (-fsanitize=fuzzer,address,undefined,
# -O1 -g) from its sources into DIR/bin (default build/fuzz), started from the
# seed corpus tests/fuzz/corpus/TARGET (copied to DIR/corpus/TARGET, which
# grows) and run for SECONDS (default 600) with a 5 s per-input timeout (a
# hang counts as a finding) and a 2 GB memory limit; N targets at a time
# (default 2). Prints per target: executions, exec/s, coverage (libFuzzer's
# cov: edges and ft: features), corpus size, findings; a finding's input is
# kept in DIR/findings/TARGET (add it to tests/fuzz/crashes/TARGET once fixed:
# ctest replays those). Exit 0 when no target found anything, 1 otherwise,
# 2 on bad arguments, 77 when clang with libFuzzer is missing.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(cd "$here/../.." && pwd)
time_s=600 jobs=2 out=$top/build/fuzz
targets=()
missing_value() { echo "run.sh: $1 (see --help)" >&2; exit 2; }   # a usage error: exit 2
while [ $# -gt 0 ]; do
    case "$1" in
        -h|--help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        --time) time_s=${2:-}; shift ;;
        --jobs) jobs=${2:-}; shift ;;
        --out) [ -n "${2:-}" ] || missing_value "--out needs a folder"; out=$2; shift ;;
        config|coeffs|simcsv|image) targets+=("$1") ;;
        *) echo "run.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
[[ "$time_s" =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: --time: '$time_s' is not a positive whole number" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: --jobs: '$jobs' is not a positive whole number" >&2; exit 2; }
[ ${#targets[@]} -gt 0 ] || targets=(config coeffs simcsv image)
cc=$(command -v clang || command -v clang-14 || true)
[ -n "$cc" ] || { echo "run.sh: clang not found (apt-get install clang)" >&2; exit 77; }
echo 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { (void)d; (void)n; return 0; }' \
    > "${TMPDIR:-/tmp}/fz_probe.c"
"$cc" -fsanitize=fuzzer "${TMPDIR:-/tmp}/fz_probe.c" -o "${TMPDIR:-/tmp}/fz_probe" 2>/dev/null \
    || { echo "run.sh: $cc cannot build a libFuzzer target (libclang-rt / compiler-rt missing)" >&2; exit 77; }
rm -f "${TMPDIR:-/tmp}/fz_probe.c" "${TMPDIR:-/tmp}/fz_probe"

flags=(-fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -O1 -g -std=c11)
sources() {  # sources TARGET: the compiler arguments of a target
    case "$1" in
        config) echo "$here/fuzz_config.c $top/regime/kernel/swr_params.c -I$top/regime/kernel -D_GNU_SOURCE -lm" ;;
        coeffs) echo "-D_GNU_SOURCE $here/fuzz_coeffs.c $top/wallmodel/core/sww_*.c" \
                     "$top/regime/physics/*.c -I$top/wallmodel/core -I$top/regime/physics -lm" ;;
        simcsv) echo "$here/fuzz_simcsv.c $top/tools/snowphoto/swi_compare.c $top/tools/snowphoto/swi_homography.c" \
                     "$top/tools/snowphoto/swi_image.c $top/tools/snowphoto/swi_error.c -I$top/tools/snowphoto" \
                     "$top/common/swo_out.c $top/common/swo_list.c -I$top/common" \
                     "-D_XOPEN_SOURCE=700 $(pkg-config --cflags --libs gsl libpng libjpeg) -lm" ;;
        image)  echo "$here/fuzz_image.c $top/tools/snowphoto/swi_image.c $top/tools/snowphoto/swi_error.c" \
                     "$top/common/swo_out.c $top/common/swo_list.c -I$top/common" \
                     "-I$top/tools/snowphoto -D_XOPEN_SOURCE=700 -DSWI_IMAGE_MAX_PIXELS=4000000" \
                     "-DSWI_IMAGE_MAX_SIDE=4000 $(pkg-config --cflags --libs libpng libjpeg) -lm" ;;
    esac
}
mkdir -p "$out/bin" "$out/corpus" "$out/findings" "$out/logs"
for t in "${targets[@]}"; do
    # shellcheck disable=SC2046
    "$cc" "${flags[@]}" -I"$here" $(eval echo $(sources "$t")) -o "$out/bin/fuzz_$t" \
        || { echo "run.sh: building fuzz_$t failed" >&2; exit 1; }
    mkdir -p "$out/corpus/$t" "$out/findings/$t"
    cp -n "$here/corpus/$t/"* "$out/corpus/$t/" 2>/dev/null || true
done

run_one() {  # run_one TARGET
    local t=$1
    (cd "$out/findings/$t" && ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
        UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
        "$out/bin/fuzz_$t" -max_total_time="$time_s" -timeout=5 -rss_limit_mb=2048 \
        -print_final_stats=1 "$out/corpus/$t" > "$out/logs/$t.log" 2>&1) || true
}
echo "run.sh: ${targets[*]}, $time_s s each, $jobs at a time, in $out"
pids=()
for t in "${targets[@]}"; do
    run_one "$t" &
    pids+=($!)
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
done
wait
found=0
printf '%-8s %12s %8s %6s %7s %7s %s\n' target execs exec/s cov ft corpus findings
for t in "${targets[@]}"; do
    l=$out/logs/$t.log
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$l" | tail -1)
    eps=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$l" | tail -1)
    last=$(grep -E '^#[0-9]+' "$l" | tail -1)
    cov=$(echo "$last" | sed -n 's/.*cov: \([0-9]*\).*/\1/p')
    ft=$(echo "$last" | sed -n 's/.*ft: \([0-9]*\).*/\1/p')
    corp=$(echo "$last" | sed -n 's/.*corp: \([0-9]*\).*/\1/p')
    nf=$(find "$out/findings/$t" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
    grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|SUMMARY: ' "$l" && nf=$((nf > 0 ? nf : 1))
    [ "$nf" -eq 0 ] || found=1
    printf '%-8s %12s %8s %6s %7s %7s %s\n' "$t" "${execs:-?}" "${eps:-?}" "${cov:-?}" "${ft:-?}" "${corp:-?}" "$nf"
done
[ "$found" = 0 ] || { echo "run.sh: findings: see $out/logs and $out/findings" >&2; exit 1; }
