#!/usr/bin/env bash
# ctest install_consumer: `cmake --install` into a scratch prefix, then what a user does with it,
# outside the source tree: a C program built through pkg-config (shared, then static), through
# find_package(gembem), run; the installed command (found through its RUNPATH) on a scene; the
# installed Python package, by itself, finding that command and library and not this checkout's.
#   test_install.sh BUILD_DIR SOURCE_DIR VERSION   ($GB_CONSUMER_FLAGS: the build's sanitizer flags)
set -uo pipefail
build=$1; src=$2; version=$3
. "$src/tools/lib.sh"
gb_test_begin
p=$out/prefix; scene=$src/validation/three_discs/case1.yaml
flags=(${GB_CONSUMER_FLAGS:-})
unset GEMBEM GEMBEM_LIBRARY PYTHONPATH LD_LIBRARY_PATH
export PATH=/usr/bin:/bin   # no gembem on it: the installed files must find each other

cmake --install "$build" --prefix "$p" >"$out/install.log" 2>&1 && ok "cmake --install" || bad "cmake --install: $(tail -3 "$out/install.log")"
for f in bin/gembem lib/libgembem.so.0 lib/libgembem.a lib/pkgconfig/gembem.pc lib/cmake/gembem/gembemConfig.cmake \
         lib/cmake/gembem/gembemConfigVersion.cmake lib/python3/dist-packages/gembem/__init__.py \
         lib/python3/dist-packages/gembem/_paths.py share/gembem/examples/demo/demo.py; do
  [ -e "$p/$f" ] && ok "installed $f" || bad "missing $f"
done
soname=$(readelf -d "$p/lib/libgembem.so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = "libgembem.so.${version%%.*}" ] && ok "SONAME $soname" || bad "SONAME '$soname'"
[ "$(readlink -f "$p/lib/libgembem.so")" = "$(readlink -f "$p/lib/libgembem.so.$version")" ] \
  && ok "libgembem.so -> libgembem.so.$version" || bad "libgembem.so does not lead to libgembem.so.$version"
headers_src=$(cd "$src/include/gembem" && ls *.h); headers_inst=$(cd "$p/include/gembem" && ls)
[ "$headers_src" = "$headers_inst" ] && ok "include/gembem: the public headers only" || bad "include/gembem: $headers_inst"

# pkg-config, shared: the program finds libgembem.so.0 through its RUNPATH
export PKG_CONFIG_PATH=$p/lib/pkgconfig
cp "$src/tests/install/consumer/consumer.c" "$out/"
cd "$out"
if cc -std=c11 "${flags[@]}" consumer.c $(pkg-config --cflags --libs gembem) -Wl,-rpath,"$p/lib" -lm -o consumer_pc 2>cc.log; then
  ./consumer_pc "$scene" "$version" && ok "pkg-config: built and run" || bad "pkg-config: the program failed"
else bad "pkg-config: $(cat cc.log)"; fi
# pkg-config --static: libgembem.a and every library it needs (Requires.private, Libs.private)
libs=$(pkg-config --static --libs gembem)
if cc -std=c11 "${flags[@]}" consumer.c $(pkg-config --cflags gembem) ${libs/-lgembem/-l:libgembem.a} -lm -o consumer_static 2>cc.log; then
  readelf -d consumer_static | grep -q 'libgembem' && bad "pkg-config --static: linked libgembem.so" \
    || { ./consumer_static "$scene" "$version" && ok "pkg-config --static: built and run" || bad "pkg-config --static: the program failed"; }
else bad "pkg-config --static: $(head -5 cc.log)"; fi
# find_package(gembem) and gembem::gembem
if cmake -S "$src/tests/install/consumer" -B cm -DCMAKE_PREFIX_PATH="$p" -DCMAKE_C_FLAGS="${flags[*]}" >cm.log 2>&1 \
   && cmake --build cm >>cm.log 2>&1; then
  cm/consumer "$scene" "$version" && ok "find_package: built and run" || bad "find_package: the program failed"
else bad "find_package: $(tail -5 cm.log)"; fi
# the installed command: its library through RUNPATH, a scene to its end
[ "$("$p/bin/gembem" --version)" = "gembem $version" ] && ok "gembem --version" || bad "gembem --version: $("$p/bin/gembem" --version 2>&1)"
for c in run bem pack; do
  "$p/bin/gembem" $c --help | grep -q "usage: gembem $c" && ok "gembem $c --help" || bad "gembem $c --help"
done
"$p/bin/gembem" run "$scene" -o run --quiet 2>run.log && [ -s run/steps.csv ] && ok "installed gembem runs the three discs" \
  || bad "installed gembem run: $(cat run.log)"
# the installed Python package: imported with /usr/bin/python3 from the prefix, finds the installed command
found=$(PYTHONPATH=$p/lib/python3/dist-packages /usr/bin/python3 -c "import gembem; print(gembem.find_gembem())" 2>&1)
[ "$found" = "$p/bin/gembem" ] && ok "Python: find_gembem() is the installed command" || bad "Python: find_gembem() gave '$found'"
ratio=$(PYTHONPATH=$p/lib/python3/dist-packages /usr/bin/python3 -c "import gembem; print(gembem.Run('run').steps['step'][-1])" 2>&1)
[ "$ratio" = "110" ] && ok "Python: the installed package reads the run (110 steps)" || bad "Python: read '$ratio'"
# the installed Python package in-process: the installed library (not this checkout's), one step of the three discs
# (a sanitized library needs the sanitizers' runtimes preloaded into python3: GB_SANITIZER_PRELOAD)
inproc=(env PYTHONPATH=$p/lib/python3/dist-packages)
[ -n "${GB_SANITIZER_PRELOAD:-}" ] && inproc+=(LD_PRELOAD=$GB_SANITIZER_PRELOAD ASAN_OPTIONS=detect_leaks=0)
lib=$("${inproc[@]}" /usr/bin/python3 -c "import gembem.library as l; print(l.find_library())" 2>&1)
[ "$lib" = "$p/lib/libgembem.so.0" ] && ok "Python: find_library() is the installed library" || bad "Python: find_library() gave '$lib'"
stepped=$("${inproc[@]}" /usr/bin/python3 -c "
import gembem
sim = gembem.Simulation('$scene')
sim.step()
r = sim.step()
print(r.step, sim.grains.nrows, gembem.library.version())" 2>&1)
[ "$stepped" = "1 3 $version" ] && ok "Python: gembem.Simulation takes step 1 of the three discs in-process" \
  || bad "Python: in-process step gave '$stepped'"
gb_test_end
