#!/usr/bin/env bash
# Build the Debian package from a build tree, unpack it into a scratch root (not the
# machine: `apt install` would need root and change the system) and check that
#   - it holds the command, the module for Debian's python3 and the workbench in
#     FreeCAD's system Mod folder, with dependencies on OpenCASCADE found by
#     dpkg-shlibdeps;
#   - the unpacked command meshes a shipped example;
#   - the unpacked module imports in /usr/bin/python3 and meshes it;
#   - FreeCAD (freecadcmd) loads the unpacked workbench, with the unpacked module,
#     and meshes a part through make_mesh.
# Usage: tests/package/test_debian_package.sh BUILD_DIR
set -euo pipefail

build=$(cd "${1:?usage: $0 BUILD_DIR}" && pwd)
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/tq_deb.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cpack --config "$build/CPackConfig.cmake" -B "$scratch/out" >"$scratch/cpack.log" 2>&1 ||
  { cat "$scratch/cpack.log"; fail "cpack -G DEB failed"; }
deb=$(ls "$scratch"/out/templatequad_*.deb)
echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) kB)"

depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
[[ "$depends" == *libocct-data-exchange* ]] || fail "no dependency on OpenCASCADE's data exchange library"
[[ "$depends" == *python3-numpy* ]] || fail "no dependency on python3-numpy"
[[ "$(dpkg-deb -f "$deb" Maintainer)" == "TemplateQuad contributors"* ]] || fail "maintainer"

root="$scratch/root"
dpkg-deb -x "$deb" "$root"
mod="$root/usr/share/freecad/Mod/TemplateQuad"
for path in usr/bin/tquad usr/lib/templatequad/tquad_cad.so usr/lib/templatequad/tquad_step.so \
            usr/lib/templatequad/tquad_iges.so \
            usr/lib/python3/dist-packages/tquad/__init__.py \
            usr/share/freecad/Mod/TemplateQuad/package.xml \
            usr/share/freecad/Mod/TemplateQuad/LICENSE \
            usr/share/freecad/Mod/TemplateQuad/freecad_workbench/freecad/templatequad/factory.py \
            usr/share/freecad/Mod/TemplateQuad/freecad_workbench/resources/icons/TemplateQuad.svg \
            usr/share/doc/templatequad/copyright; do
  [[ -e "$root/$path" ]] || fail "/$path is not in the package"
done
compgen -G "$root/usr/lib/python3/dist-packages/tquad/_core*.so" >/dev/null || fail "no compiled module"
if find "$root" -name __pycache__ | grep -q .; then fail "the package holds __pycache__ folders"; fi

example="$repo/resources/shapes/plate_with_hole.step"
"$root/usr/bin/tquad" mesh "$example" -o "$scratch/plate.vtu" >"$scratch/cli.log" ||
  { cat "$scratch/cli.log"; fail "the packaged tquad could not mesh $example"; }
[[ -s "$scratch/plate.vtu" ]] || fail "the packaged tquad wrote no mesh"
# The command links no OpenCASCADE library; its CAD layer is loaded from its modules.
if readelf -d "$root/usr/bin/tquad" | grep -q 'NEEDED.*libTK'; then fail "/usr/bin/tquad links OpenCASCADE"; fi
echo "command: $(grep -m1 quads "$scratch/cli.log" | sed 's/^ *//')"

PYTHONPATH="$root/usr/lib/python3/dist-packages" /usr/bin/python3 - "$example" "$root" <<'PY'
import sys
import tquad
assert tquad.__file__.startswith(sys.argv[2]), f"tquad imported from {tquad.__file__}"
mesh = tquad.mesh_shape(sys.argv[1])
assert len(mesh.quads) > 0 and not mesh.refused_faces
print(f"module: {len(mesh.quads)} quads from {tquad.__file__}")
PY

if ! command -v freecadcmd >/dev/null 2>&1; then
  echo "skipped: the workbench in FreeCAD (freecadcmd not installed)"
  exit 0
fi
# FreeCAD's system Mod folder is /usr/share/freecad/Mod; the scratch root's stands in
# for it as the user Mod folder of a temporary FreeCAD home.
home="$scratch/home"
mkdir -p "$home/Mod"
ln -s "$mod" "$home/Mod/TemplateQuad"
cat >"$scratch/freecad_check.py" <<PY
import os, sys
import FreeCAD, Part
import freecad.templatequad as addon
import tquad
root = "$root"
assert os.path.realpath(addon.__file__).startswith(root), addon.__file__
assert tquad.__file__.startswith(root), tquad.__file__
doc = FreeCAD.newDocument("Package")
part = doc.addObject("Part::Feature", "Plate")
part.Shape = Part.read("$example")
doc.recompute()
mesh = addon.make_mesh(doc, part)
assert mesh.FemMesh.QuadrangleCount > 0 and not mesh.Incomplete
print(f"FreeCAD: {mesh.FemMesh.QuadrangleCount} quads through the packaged workbench")
sys.exit(0)
PY
FREECAD_USER_HOME="$home" PYTHONPATH="$root/usr/lib/python3/dist-packages" timeout 300 \
  freecadcmd -c "exec(open('$scratch/freecad_check.py').read())" >"$scratch/freecad.log" 2>&1 ||
  { cat "$scratch/freecad.log"; fail "FreeCAD could not mesh with the packaged workbench"; }
grep "FreeCAD:" "$scratch/freecad.log"
echo "passed"
