#!/bin/sh
# run-bench.sh OUT_DIR LIMIT_BINARY LESSON_BINARY...: what `make bench` runs.
#
# Runs the limit first, then each lesson's benchmark, in this one invocation;
# prints one table and writes OUT_DIR/results.csv. Every binary prints CSV
# lines with the columns of tests/bench/measure.h; here they get the derived
# figures: million triangles and million fragments per second, nanoseconds
# per triangle and per fragment, and the ratio of fragments per second to
# the limit's.
# When Mesa's llvmpipe is among them (rows llvmpipe_0t and llvmpipe_1t, timed
# in CPU time of the process, and llvmpipe_Nt, all cores, by the wall clock),
# a second table gives each lesson's speed as a multiple of llvmpipe's on the
# same workload: on one core, of the faster of llvmpipe_0t and llvmpipe_1t.
# With lesson 10 among them and more than one core, each round also times the
# cores side by side: lesson 10's one-thread row of fill_back_to_front alone,
# then in as many copies at once as there are cores, all by the wall clock
# (bench.c's BENCH_CONFIG and BENCH_WALL_CLOCK). If each copy takes longer
# than the one alone (cores that share one, or a host running other work),
# no program's N threads can be N times as fast as its one here: that
# ceiling, how many times the frames of one alone the copies drew, is
# printed after the targets: of the round where it was highest, the copies
# of one round taken together (each copy's best round would add up to more
# than the cores gave at any one time).
# The machine line names the CPU, how many there are and, as lscpu says, how
# many threads each core runs (two threads of one core share it: there a
# program's two threads gain far less than twice one's).
# CC and BENCH_CFLAGS, when set, are shown with the machine, and so are the
# instructions lesson 10 and llvmpipe may use. BENCH_AS measures both as on
# a lesser x86-64: avx2, one with AVX2 but not AVX-512 (lesson 10's AVX2
# kernel, llvmpipe without AVX-512); sse, one without AVX (its SSE2 kernel,
# llvmpipe with SSE4.1 at most): FAST_RASTER_SIMD and Mesa's
# GALLIUM_OVERRIDE_CPU_CAPS, which can also be set by hand.
# bench_round_trip, among them and with more than one core, gives each
# round's round trip of a cache line between two threads: threads that pass
# data, as lesson 10's, gain less the longer it is (docs/performance.md,
# "Two cores far apart"); printed with the targets, not a row of the table.
# BENCH_BUSY=1 runs a loop beside them from the first program to the last,
# as other work on a shared machine (docs/performance.md, "A busy machine");
# the cores side by side then show what is left for threads.
# Every binary runs BENCH_ROUNDS times (3 unless set), the rounds one after
# the other, and each row is its round with the least median: on a shared
# machine a burst of other work slows one round of one binary, not a ratio.
set -eu
if [ $# -lt 3 ]; then
    echo "usage: run-bench.sh OUT_DIR LIMIT_BINARY LESSON_BINARY..." >&2
    exit 2
fi
out_dir=$1
shift
mkdir -p "$out_dir"
raw="$out_dir/raw.csv"
: >"$raw"

model=$(lscpu 2>/dev/null | sed -n 's/^Model name: *//p' | head -n 1)
[ -n "$model" ] || model=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1)
cpus=$(nproc 2>/dev/null || echo "?")
smt=$(lscpu 2>/dev/null | sed -n 's/^Thread(s) per core: *\([0-9]*\)$/\1/p' | head -n 1)
case $smt in
    '') ;;
    1) smt=" (1 thread per core)" ;;
    *) smt=" ($smt threads per core)" ;;
esac
compiler=$(${CC:-cc} --version 2>/dev/null | head -n 1)
echo "machine: ${model:-unknown CPU}, $cpus CPUs$smt; compiler: ${compiler:-unknown}; flags: ${BENCH_CFLAGS:-?}"
case ${BENCH_AS:-} in
    '') ;;
    avx2) FAST_RASTER_SIMD=avx2 GALLIUM_OVERRIDE_CPU_CAPS=avx # Mesa's avx: all but AVX-512
          echo "as an x86-64 with AVX2, without AVX-512 (BENCH_AS=avx2):" ;;
    sse) FAST_RASTER_SIMD=sse2 GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 # SSE4.1 at most
         echo "as an x86-64 without AVX (BENCH_AS=sse):" ;;
    *) echo "run-bench.sh: BENCH_AS: '$BENCH_AS' is not avx2 or sse" >&2; exit 2 ;;
esac
[ -z "${FAST_RASTER_SIMD:-}" ] || export FAST_RASTER_SIMD
[ -z "${GALLIUM_OVERRIDE_CPU_CAPS:-}" ] || export GALLIUM_OVERRIDE_CPU_CAPS
simd=${FAST_RASTER_SIMD:+FAST_RASTER_SIMD=$FAST_RASTER_SIMD}
caps=${GALLIUM_OVERRIDE_CPU_CAPS:+GALLIUM_OVERRIDE_CPU_CAPS=$GALLIUM_OVERRIDE_CPU_CAPS}
echo "instructions: lesson 10's kernels ${simd:-the widest the CPU has}; llvmpipe ${caps:-all the CPU has}"

case ${BENCH_BUSY:-0} in
    0) ;;
    1) # the loop: killed on the way out, and done when this script is gone
       sh -c 'while kill -0 "$1" 2>/dev/null; do :; done' run-bench-busy $$ &
       busy=$!
       trap 'kill "$busy" 2>/dev/null; wait "$busy" 2>/dev/null || :' EXIT
       trap 'exit 130' INT
       trap 'exit 143' TERM
       echo "busy: a loop runs beside every program (BENCH_BUSY=1), as other work on a shared machine" ;;
    *) echo "run-bench.sh: BENCH_BUSY: '$BENCH_BUSY' is not 0 or 1" >&2; exit 2 ;;
esac

rounds=${BENCH_ROUNDS:-3}
case $rounds in
    [1-9]) ;;
    *) echo "run-bench.sh: BENCH_ROUNDS: '$rounds' is not 1 to 9" >&2; exit 2 ;;
esac
all="$out_dir/rounds.csv"
: >"$all"
# side_by_side BINARY: rows cores_alone_R and cores_copy_R_1 .. cores_copy_R_N into $all (round R).
side_by_side() {
    echo "running $(basename "$1") on fill_back_to_front, alone then $cpus at once ..." >&2
    BENCH_CONFIG=0 BENCH_WALL_CLOCK=1 "$1" fill_back_to_front >"$out_dir/copy.0"
    sed "s/^[^,]*,/cores_alone_$round,/" "$out_dir/copy.0" >>"$all"
    rm -f "$out_dir/copy.0"
    pids=
    for k in $(seq "$cpus"); do
        BENCH_CONFIG=0 BENCH_WALL_CLOCK=1 "$1" fill_back_to_front >"$out_dir/copy.$k" &
        pids="$pids $!"
    done
    failed=0
    for pid in $pids; do
        wait "$pid" || failed=1
    done
    for k in $(seq "$cpus"); do
        sed "s/^[^,]*,/cores_copy_${round}_$k,/" "$out_dir/copy.$k" >>"$all"
        rm -f "$out_dir/copy.$k"
    done
    [ "$failed" = 0 ] || { echo "run-bench.sh: a copy of $(basename "$1") failed" >&2; exit 1; }
}
for round in $(seq "$rounds"); do
    for bin in "$@"; do
        case $(basename "$bin"):$cpus in
            bench_round_trip:1 | bench_round_trip:\?) continue ;; # one core: no round trip
            bench_round_trip:*) "$bin" | sed "s/^round_trip,/round_trip_$round,/" >>"$all"; continue ;;
        esac
        echo "running $(basename "$bin"), round $round of $rounds ..." >&2
        "$bin" >>"$all"
        case $(basename "$bin"):$cpus in
            bench_10_fast_raster:1 | bench_10_fast_raster:\?) ;;
            bench_10_fast_raster:*) side_by_side "$bin" ;;
        esac
    done
done
# Each row (lesson, workload) once, in the order first seen: the round with
# the least median. Every round must have left the same depth buffer.
awk -F, '{
    k = $1 "," $2
    if (!(k in best)) { order[++n] = k; best[k] = $0; med[k] = $8 + 0; sum[k] = $11; next }
    if ($11 != sum[k]) {
        printf("run-bench.sh: %s: rounds left different depth buffers\n", k) > "/dev/stderr"
        failed = 1
    }
    if ($8 + 0 < med[k]) { best[k] = $0; med[k] = $8 + 0 }
}
END {
    for (i = 1; i <= n; i++)
        print best[order[i]]
    exit failed
}' "$all" >"$raw"
rm -f "$all"

awk -F, -v csv="$out_dir/results.csv" -v rounds="$rounds" '
function check(what, got, want) {
    printf("  %-62s %5.2f (want >= %.2f) %s\n", what, got, want, (got >= want) ? "met" : "MISSED")
}
BEGIN {
    print("lesson,workload,width,height,reps,triangles,fragments,median_s,min_s,max_s," \
          "mtri_per_s,ns_per_triangle,mfrag_per_s,ns_per_fragment,ratio_to_limit,spread," \
          "depth_checksum") > csv
}
NR == 1 {
    # BENCH_WARMUP and BENCH_REPS of tests/bench/measure.h
    printf("each row: the best of %d rounds; a round: 1 untimed warm-up, then %d timed\n", rounds, $5)
    printf("repetitions of a frame (clear, every corner from clip space on, draw; llvmpipe:\n")
    printf("clear, draw and glFinish), in CPU time for 0 or 1 thread, by the wall clock for N;\n")
    printf("a row: the median of its best round; spread = (slowest - fastest) / median\n\n")
    printf("%-22s %-19s %9s %10s %9s %7s %8s %8s %8s %8s %8s\n", "lesson", "workload", "triangles",
           "fragments", "median ms", "spread", "Mtri/s", "ns/tri", "Mfrag/s", "ns/frag", "x limit")
}
{
    lesson = $1; workload = $2; tris = $6 + 0; frags = $7 + 0; med = $8; lo = $9; hi = $10
    if (med <= 0)
        med = 1e-9 # below the resolution of the clock: no division by zero
    if (lesson ~ /^cores_alone_[0-9]+$/) { # the cores side by side: not rows of the table
        split(lesson, f, "_")
        alone[f[3]] = med
        next
    }
    if (lesson ~ /^round_trip_[0-9]+$/) { # the round trip of round f[3]
        split(lesson, f, "_")
        trip[f[3] + 0] = med
        trips = (f[3] + 0 > trips) ? f[3] + 0 : trips
        next
    }
    if (lesson ~ /^cores_copy_[0-9]+_[0-9]+$/) { # round f[3], copy f[4]
        split(lesson, f, "_")
        copy[f[3], f[4]] = med
        copies = (f[4] + 0 > copies) ? f[4] + 0 : copies
        next
    }
    mfrag = frags / med / 1e6
    if (lesson == "limit" && workload == "fill_back_to_front")
        limit = mfrag
    ratio = (limit > 0) ? mfrag / limit : 0
    spread = (hi - lo) / med
    mtri = (tris > 0) ? sprintf("%.3g", tris / med / 1e6) : "-"
    ntri = (tris > 0) ? tris : "-"
    nsf = (frags > 0) ? med / frags * 1e9 : 0
    nst = (tris > 0) ? sprintf("%.1f", med / tris * 1e9) : "-"
    printf("%-22s %-19s %9s %10d %9.2f %6.1f%% %8s %8s %8.1f %8.2f %8.2f\n", lesson, workload,
           ntri, frags, med * 1e3, spread * 100, mtri, nst, mfrag, nsf, ratio)
    printf("%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.3f,%.4f,%.4f,%.4f,%s\n", lesson, workload,
           $3, $4, $5, tris, frags, med, lo, hi, (tris > 0) ? sprintf("%.6g", tris / med / 1e6) : "",
           (tris > 0) ? nst : "", mfrag, nsf, ratio, spread, $11) > csv
    rows++
    row_lesson[rows] = lesson
    row_workload[rows] = workload
    row_tri_rate[rows] = tris / med / 1e6
    row_ratio[rows] = ratio
    row_med[rows] = med
    if (lesson == "llvmpipe_0t" || lesson == "llvmpipe_1t") {
        # the peer on one core at its best: the faster of the two
        if (!(workload in gpu1) || med < gpu1[workload]) {
            gpu1[workload] = med
            gpu1_name[workload] = lesson
        }
    } else if (lesson ~ /^llvmpipe_[0-9]+t$/) {
        gpuN[workload] = med
        gpuN_name = lesson
    }
}
# The targets docs/performance.md states: on fill_back_to_front 0.40 of the
# limit for lesson 04, 0.20 for the others; on small 3 million triangles/s.
END {
    # Mesa llvmpipe in the same run (tests/gpu/bench_llvmpipe.c): the speed of each
    # lesson as a multiple of that of llvmpipe on the same workload (the
    # median time of llvmpipe over that of the lesson), one thread, all cores.
    if (length(gpu1) > 0) {
        print ""
        printf("speed relative to llvmpipe (time of llvmpipe / time of the lesson; above 1: the lesson is faster):\n")
        printf("%-22s %-19s %10s %-12s %10s\n", "lesson", "workload", "x 1 thread", "(its best)",
               "x " (gpuN_name != "" ? gpuN_name : "all cores"))
        for (r = 1; r <= rows; r++) {
            l = row_lesson[r]
            w = row_workload[r]
            if (l == "limit" || l ~ /^llvmpipe_/ || !(w in gpu1))
                continue
            printf("%-22s %-19s %10.2f %-12s %10s\n", l, w, gpu1[w] / row_med[r], gpu1_name[w],
                   (w in gpuN) ? sprintf("%.2f", gpuN[w] / row_med[r]) : "-")
        }
    }
    print ""
    print "targets (single-threaded, but the N-thread rows of lesson 10):"
    for (r = 1; r <= rows; r++) {
        l = row_lesson[r]
        w = row_workload[r]
        if (l ~ /^llvmpipe_/)
            continue
        # Lesson 10 (docs/performance.md): twice llvmpipe at its best on one
        # core, 1.5 times llvmpipe on all cores, each with as many threads;
        # and on all cores 1.8 times itself on one where tiles share out well.
        if (l == "10_fast_raster_1t") {
            med10[w] = row_med[r]
            if (w in gpu1)
                check(l " " w ", speed / " gpu1_name[w], gpu1[w] / row_med[r], 2.0)
        }
        if (l ~ /^10_fast_raster_[0-9]+t$/ && l != "10_fast_raster_1t") {
            if (w in gpuN)
                check(l " " w ", speed / " gpuN_name, gpuN[w] / row_med[r], 1.5)
            if ((w in med10) && (w == "medium" || w ~ /^fill_/))
                check(l " " w ", speed / 10_fast_raster_1t", med10[w] / row_med[r], 1.8)
        }
        if (w == "fill_back_to_front" && l != "limit")
            check(l " fill_back_to_front, fraction of the limit", row_ratio[r],
                  (l ~ /^04/) ? 0.40 : 0.20)
        if (w == "small" && l != "limit")
            check(l " small, million triangles per second", row_tri_rate[r], 3)
        if (l ~ /^08_/)
            med08[w] = row_med[r]
        if (l ~ /^09_/)
            med09[w] = row_med[r]
    }
    # The cores side by side: N copies at once did N frames in the time of
    # sum(alone / copy k) frames alone; N threads can share no better. The
    # round where they did the most, its copies together.
    best = -1
    for (r in alone) {
        if (copies < 2)
            break
        ceiling = 0; slowest = 0
        for (k = 1; k <= copies; k++) {
            ceiling += alone[r] / copy[r, k]
            slowest = copy[r, k] > slowest ? copy[r, k] : slowest
        }
        if (ceiling > best) {
            best = ceiling; best_slowest = slowest; best_alone = alone[r]
        }
    }
    if (best > 0) {
        printf("  the cores side by side, their best round: %d copies of 10_fast_raster_1t on fill_back_to_front at once\n",
               copies)
        printf("    drew %.2f times the frames of one alone (%.2f ms a frame at the slowest, %.2f alone):\n",
               best, best_slowest * 1e3, best_alone * 1e3)
        printf("    about the most %d threads can gain over one on this machine\n", copies)
    }
    # A cache line between two threads and back, each round (bench_round_trip).
    if (trips > 0) {
        line = ""
        for (r = 1; r <= trips; r++)
            line = line ((r in trip) ? sprintf("%s%.0f", (line != "") ? ", " : "", trip[r] * 1e9) : "")
        printf("  the round trip of a cache line from one thread to the other and back: %s ns\n", line)
        printf("    (a round each; threads that pass data, as those of lesson 10, gain less the longer it is)\n")
    }
    # Lesson 09 against lesson 08 (docs/09_hierarchical_z.md): the time of 08 over that of 09.
    if (("city" in med08) && ("city" in med09))
        check("09 on city, times as fast as 08", med08["city"] / med09["city"], 3)
    if (("fill_back_to_front" in med08) && ("fill_back_to_front" in med09))
        check("09 on fill_back_to_front, times as fast as 08 (nothing hidden)", \
              med08["fill_back_to_front"] / med09["fill_back_to_front"], 1 / 1.1)
}' "$raw"
rm -f "$raw"
echo
echo "wrote $out_dir/results.csv"
