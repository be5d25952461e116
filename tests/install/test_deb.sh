#!/usr/bin/env bash
# ctest install_deb: `cpack -G DEB` builds the Debian package; its Depends name the runtime
# libraries gembem links and the Python package's modules, each a package this Debian knows; its
# files are what a user needs; unpacked into a scratch root (dpkg -x: no root, no dpkg database),
# the packaged gembem runs the three discs and the packaged demo runs from the packaged files.
#   test_deb.sh BUILD_DIR SOURCE_DIR VERSION
set -uo pipefail
build=$1; src=$2; version=$3
for tool in cpack dpkg-deb dpkg-shlibdeps dpkg-query; do
  command -v $tool >/dev/null || { echo "SKIP: $tool not found (Debian's dpkg-dev, cmake)"; exit 77; }
done
. "$src/tools/lib.sh"
gb_test_begin
unset GEMBEM PYTHONPATH LD_LIBRARY_PATH
export PATH=/usr/bin:/bin   # no gembem on it: the packaged files must find each other

(cd "$build" && cpack -G DEB -B "$out/cpack") >"$out/cpack.log" 2>&1 && ok "cpack -G DEB" || bad "cpack: $(tail -5 "$out/cpack.log")"
deb=$out/cpack/gembem_${version}_amd64.deb
[ -f "$deb" ] && ok "gembem_${version}_amd64.deb" || { bad "no $deb: $(ls "$out/cpack")"; gb_test_end; exit; }

[ "$(dpkg-deb -f "$deb" Package)" = gembem ] && ok "Package: gembem" || bad "Package: $(dpkg-deb -f "$deb" Package)"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] && ok "Version: $version" || bad "Version: $(dpkg-deb -f "$deb" Version)"
[ -n "$(dpkg-deb -f "$deb" Maintainer)" ] && ok "Maintainer: $(dpkg-deb -f "$deb" Maintainer)" || bad "no Maintainer"
depends=$(dpkg-deb -f "$deb" Depends)
for p in libcholmod3 libumfpack5 liblapacke libopenblas0 libgmsh4.8 libfyaml0 libqhull-r8.0 libgomp1 libc6 \
         python3-numpy python3-matplotlib python3-yaml; do
  [[ ",$depends," == *", $p"[\ ,]* || "$depends" == "$p"[\ ,]* ]] && ok "Depends: $p" || bad "Depends lacks $p: $depends"
done
# every dependency (its first alternative) is a package of this Debian, installed here
IFS=, read -ra deps <<<"$depends"
for d in "${deps[@]}"; do
  name=$(echo "$d" | sed 's/^ *//; s/[ (|].*//')
  dpkg-query -W -f='${Status}' "$name" 2>/dev/null | grep -q "install ok installed" && ok "Depends: $name is a Debian package" \
    || bad "Depends: $name is not an installed package"
done
contents=$(dpkg-deb -c "$deb" | awk '{print $6}')
for f in ./usr/bin/gembem ./usr/lib/libgembem.so.$version ./usr/lib/libgembem.a ./usr/include/gembem/gembem.h \
         ./usr/lib/pkgconfig/gembem.pc ./usr/lib/cmake/gembem/gembemConfig.cmake \
         ./usr/lib/python3/dist-packages/gembem/__init__.py ./usr/lib/python3/dist-packages/gembem/_paths.py \
         ./usr/share/gembem/examples/demo/demo.py ./usr/share/gembem/meshes/square_cavity_sides.geo; do
  grep -qx -- "$f" <<<"$contents" && ok "contains $f" || bad "lacks $f"
done
grep -q "__pycache__\|/build/\|/tests/" <<<"$contents" && bad "build or test files packed" || ok "no build or test files"

# unpacked into a scratch root: the command (RUNPATH $ORIGIN/../lib), the Python package and the demo
root=$out/root
dpkg -x "$deb" "$root" && ok "dpkg -x" || bad "dpkg -x"
cd "$out"
export PYTHONPATH=$root/usr/lib/python3/dist-packages
"$root/usr/bin/gembem" run "$src/validation/three_discs/case1.yaml" -o three_discs --quiet 2>run.log \
  && [ "$(/usr/bin/python3 -c "import gembem; print(gembem.Run('three_discs').steps['step'][-1])")" = 110 ] \
  && ok "the packaged gembem runs the three discs (110 steps)" || bad "the packaged gembem: $(cat run.log)"
[ "$(/usr/bin/python3 -c 'import gembem; print(gembem.find_gembem())')" = "$root/usr/bin/gembem" ] \
  && ok "the packaged Python package runs the packaged gembem" || bad "find_gembem: $(/usr/bin/python3 -c 'import gembem; print(gembem.find_gembem())' 2>&1)"
if /usr/bin/python3 "$root/usr/share/gembem/examples/demo/demo.py" demo --grains 80 --steps 6 >demo.log 2>&1; then
  n=$(ls demo/figures/*.png 2>/dev/null | wc -l)
  [ "$n" -eq 4 ] && ok "the packaged demo: 4 figures" || bad "the packaged demo drew $n figures"
else bad "the packaged demo: $(tail -5 demo.log)"; fi
gb_test_end
