#!/bin/sh
# tests/fuzz/targets/fuzz.sh - the libFuzzer harness of every file reader.
#
#   sh tests/fuzz/targets/fuzz.sh build DIR          build DIR/fuzz_READER for each reader
#   sh tests/fuzz/targets/fuzz.sh run DIR SECONDS    build, then fuzz each reader SECONDS
#   sh tests/fuzz/targets/fuzz.sh once DIR           build (at -O0), then run each target
#                                            over its seeds and the regress files once
#
# `make fuzz [FUZZ_SECONDS=60]` is "run build-fuzz $(FUZZ_SECONDS)".
# The targets are tests/fuzz/targets/fuzz_reader.c compiled once per
# reader with clang's -fsanitize=fuzzer,address,undefined and linked with
# the library built the same way (in DIR/obj); the GDSII reader's target
# is tests/fuzz/fuzz_gds.c (-DS3D_LIBFUZZER), which runs the reader's
# non-exiting entry points in process; measure_args and fem_args are the
# command lines of measure and fem (tests/fuzz/targets/fuzz_args.c).  Seeds: tests/fuzz/corpus/
# READER/; the corpus a run grows: DIR/corpus/READER/; what it finds (a
# crash, a sanitizer report, a hang over 10 s, more than 1 GB):
# DIR/findings/READER-*.  Every finding, once fixed, goes to
# tests/fuzz/regress/ with a line in its EXPECT (see HACKING.md).
set -u
mode=${1:?usage: fuzz.sh build|run|once DIR [SECONDS]}
dir=${2:?usage: fuzz.sh build|run|once DIR [SECONDS]}
secs=${3:-60}
top=$(cd "$(dirname "$0")/../../.." && pwd)
# DIR is reused: an object older than its source, than a library header or
# than this script (its flags) is rebuilt, a target older than an object
# relinked
self=$top/tests/fuzz/targets/fuzz.sh
CLANG=${FUZZ_CC:-clang}
READERS="splat bleach contour stack plot2d plot3d options template rate_ascii rate_binary gds measure_args fem_args"
# -O1 for a campaign (more executions a second); "once" runs each seed
# once, where compiling is most of the time: -O0 builds the library in a
# third of the CPU time and its sanitizers check the same accesses
# (FUZZ_OPT chooses)
case $mode in once) opt=${FUZZ_OPT:--O0} ;; *) opt=${FUZZ_OPT:--O1} ;; esac
FLAGS="-g $opt -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined -D_XOPEN_SOURCE=700 -std=c11"
for d in "$top"/src/lib/*/; do FLAGS="$FLAGS -I${d%/}"; done

command -v "$CLANG" >/dev/null 2>&1 || { echo "fuzz: $CLANG is not installed (apt-get install clang libclang-rt-14-dev)" >&2; exit 77; }
mkdir -p "$dir/obj" "$dir/corpus" "$dir/findings" || exit 1
# absolute, for the targets that run in a directory of their own
dir=$(cd "$dir" && pwd) || exit 1
# built with other flags (FUZZ_OPT, the mode): everything is rebuilt
if [ "$(cat "$dir/flags" 2>/dev/null)" != "$CLANG $FLAGS" ]; then
	rm -f "$dir"/obj/*.o "$dir"/fuzz_*
	echo "$CLANG $FLAGS" >"$dir/flags" || exit 1
fi

# the library, minus the X11 preview, with coverage for the fuzzer
objs=""
for src in "$top"/src/lib/*/*.c; do
	case $src in */draw_x11.c) continue ;; esac
	objs="$objs $dir/obj/$(basename "$src" .c).o"
done
for src in "$top"/src/lib/*/*.c; do
	case $src in */draw_x11.c) continue ;; esac
	o=$dir/obj/$(basename "$src" .c).o
	if [ ! -f "$o" ] || [ "$src" -nt "$o" ] || [ "$self" -nt "$o" ] ||
	   [ -n "$(find "$top/src/lib" -name '*.h' -newer "$o" 2>/dev/null)" ]; then
		echo "$CLANG -fsanitize=fuzzer-no-link $FLAGS -c -o $o $src"
	fi
done | xargs -P 2 -I{} sh -c '{}' || { echo "fuzz: building the library failed" >&2; exit 1; }
# measure's own files for measure_args, its main renamed
mobjs=""
for src in "$top"/src/measure/*.c; do
	o=$dir/obj/measure_$(basename "$src" .c).o
	mobjs="$mobjs $o"
	if [ ! -f "$o" ] || [ "$src" -nt "$o" ] || [ "$self" -nt "$o" ] ||
	   [ -n "$(find "$top/src" -name '*.h' -newer "$o" 2>/dev/null)" ]; then
		$CLANG -fsanitize=fuzzer-no-link $FLAGS -I"$top/src/measure" -Dmain=measure_main \
			-c -o "$o" "$src" || { echo "fuzz: building measure failed" >&2; exit 1; }
	fi
done
WRAP=-Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free
for r in $READERS; do
	t=$dir/fuzz_$r
	src=$top/tests/fuzz/targets/fuzz_reader.c
	[ "$r" = gds ] && src=$top/tests/fuzz/fuzz_gds.c
	case $r in *_args) src=$top/tests/fuzz/targets/fuzz_args.c ;; esac
	if [ ! -x "$t" ] || [ "$src" -nt "$t" ] || [ "$self" -nt "$t" ] ||
	   [ -n "$(find "$dir/obj" "$top/tests/fuzz/targets" -name '*.[ho]' -newer "$t")" ]; then
		if [ "$r" = gds ]; then
			$CLANG -fsanitize=fuzzer $FLAGS -DS3D_LIBFUZZER -o "$t" "$src" $objs -lm ||
				{ echo "fuzz: linking $r failed" >&2; exit 1; }
		elif [ "$r" = measure_args ]; then
			$CLANG -fsanitize=fuzzer $FLAGS -DARGS_NAME="\"$r\"" -DMEASURE_ARGS \
				-I"$top/tests/fuzz/targets" -o "$t" $WRAP,--wrap=exit,--wrap=fclose \
				"$src" $mobjs $objs -lm || { echo "fuzz: linking $r failed" >&2; exit 1; }
		elif [ "$r" = fem_args ]; then
			$CLANG -fsanitize=fuzzer $FLAGS -DARGS_NAME="\"$r\"" -DFEM_TOP="\"$top\"" \
				-I"$top/tests/fuzz/targets" -o "$t" $WRAP \
				"$src" $objs -lm || { echo "fuzz: linking $r failed" >&2; exit 1; }
		else
			$CLANG -fsanitize=fuzzer $FLAGS -DREADER_NAME="\"$r\"" -o "$t" \
				-Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc,--wrap=free \
				"$src" $objs -lm || { echo "fuzz: linking $r failed" >&2; exit 1; }
		fi
	fi
done
[ "$mode" = build ] && exit 0

# libFuzzer options: die() messages closed (crash reports still shown),
# leaks off (a rejected input leaves what the reader allocated), a hang
# is 10 s, memory 1 GB
OPTS="-close_fd_mask=2 -detect_leaks=0 -timeout=10 -rss_limit_mb=1024 -print_final_stats=1"
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
for r in $READERS; do
	mkdir -p "$dir/corpus/$r"
	seeds=$top/tests/fuzz/corpus/$r
	log=$dir/$r.log
	case $mode in
	once)
		# the seeds, and the regress files of this reader, once each
		reg=$dir/regress-$r
		rm -rf "$reg" && mkdir -p "$reg"
		prefix=$(echo "$r" | sed 's/_.*//')
		for f in "$top"/tests/fuzz/regress/"$prefix"-*; do
			[ -f "$f" ] && cp "$f" "$reg/"
		done
		"$dir/fuzz_$r" $OPTS -runs=0 -artifact_prefix="$dir/findings/$r-" \
			"$seeds" "$reg" >"$log" 2>&1
		;;
	run)
		"$dir/fuzz_$r" $OPTS -max_total_time="$secs" \
			-artifact_prefix="$dir/findings/$r-" "$dir/corpus/$r" "$seeds" >"$log" 2>&1
		;;
	*) echo "fuzz: unknown mode $mode" >&2; exit 2 ;;
	esac
	st=$?
	execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
	echo "fuzz: $r: ${execs:-?} executions, exit $st"
	if [ $st -ne 0 ]; then
		status=1
		grep -E 'ERROR|SUMMARY|Test unit written|runtime error' "$log" | head -n 8 | sed 's/^/    /'
	fi
done
exit $status
