#!/usr/bin/env bash
# Install the TemplateQuad FreeCAD add-on for the current user, or remove it.
#
#   freecad_workbench/install.sh [TQUAD_MODULE_DIR]   install, or replace an install
#   freecad_workbench/install.sh --uninstall          remove it
#
# TQUAD_MODULE_DIR is the built Python package `tquad` (default: <repo>/build/python/tquad,
# made by `cmake --build build --target tquad_python`). It is copied into the add-on's
# workbench folder, which FreeCAD puts on sys.path, so the workbench's `import tquad`
# finds it.
#
# Where: FreeCAD 0.20 (Debian) loads user add-ons from <user data>/Mod/<Name>, the user
# data directory being $FREECAD_USER_HOME when that is set, else
# ${XDG_DATA_HOME:-~/.local/share}/FreeCAD (checked with FreeCAD.getUserAppDataDir();
# this build ignores a legacy ~/.FreeCAD). Tests set FREECAD_USER_HOME to a temporary
# directory to install there.
#
# Idempotent: the add-on folder is rebuilt in a staging folder and swapped in whole.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(dirname "$here")
user_dir="${FREECAD_USER_HOME:-${XDG_DATA_HOME:-$HOME/.local/share}/FreeCAD}"
mod_dir="$user_dir/Mod"
target="$mod_dir/TemplateQuad"

usage() {
  sed -n '2,9p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
}

is_ours() {  # the folder holds this add-on's package.xml (never delete anything else)
  grep -q '<name>TemplateQuad</name>' "$1/package.xml" 2>/dev/null
}

uninstall() {
  if [[ ! -e "$target" ]]; then
    echo "TemplateQuad is not installed in $target; nothing to remove."
    return 0
  fi
  if ! is_ours "$target"; then
    echo "error: $target exists but is not the TemplateQuad add-on; not removing it." >&2
    return 2
  fi
  rm -rf "$target"
  echo "Removed TemplateQuad from $target. Restart FreeCAD."
}

install() {
  local module="$1"
  if [[ ! -f "$module/__init__.py" ]] || ! compgen -G "$module/_core*.so" >/dev/null; then
    echo "error: no built tquad module in $module (expected __init__.py and _core*.so)." >&2
    echo "Build it first: cmake --build $repo/build --target tquad_python" >&2
    return 2
  fi
  module=$(cd "$module" && pwd)
  if [[ -e "$target" ]] && ! is_ours "$target"; then
    echo "error: $target exists but is not the TemplateQuad add-on; not replacing it." >&2
    return 2
  fi

  mkdir -p "$mod_dir"
  # Stage next to the target (same file system), so the swap below is a rename.
  local stage
  stage=$(mktemp -d "$mod_dir/.TemplateQuad.install.XXXXXX")
  trap 'rm -rf "$stage"' EXIT
  # The repository's layout (paths.py): package.xml and LICENSE at the root, the
  # workbench folder beside them, the compiled module inside it (on sys.path).
  cp "$repo/package.xml" "$repo/LICENSE" "$stage/"
  mkdir "$stage/freecad_workbench"
  cp -R "$here/freecad" "$here/resources" "$here/README.md" "$stage/freecad_workbench/"
  cp -R "$module" "$stage/freecad_workbench/tquad"
  find "$stage" -name __pycache__ -type d -prune -exec rm -rf {} +

  rm -rf "$target"
  mv "$stage" "$target"
  chmod 755 "$target"
  trap - EXIT

  # FreeCAD embeds Debian's python3: the module must import there (same ABI).
  if [[ -x /usr/bin/python3 ]] && \
     ! PYTHONPATH="$target/freecad_workbench" /usr/bin/python3 -c "import tquad" 2>/dev/null; then
    echo "warning: /usr/bin/python3 cannot import tquad from $target;" \
         "FreeCAD will report the module as missing (built for another Python?)." >&2
  fi

  echo "Installed TemplateQuad into $target"
  echo "  tquad module copied from $module"
  echo "  Restart FreeCAD and pick the 'TemplateQuad' workbench;" \
       "scripts: from freecad.templatequad import make_mesh"
  echo "  Remove with: $here/install.sh --uninstall   (or: rm -rf '$target')"
}

case "${1:-}" in
  -h|--help) usage ;;
  --uninstall) uninstall ;;
  -*) echo "error: unknown option $1" >&2; usage >&2; exit 2 ;;
  *) install "${1:-$repo/build/python/tquad}" ;;
esac
