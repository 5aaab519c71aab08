#!/usr/bin/env bash
# Installs the FreeCAD workbench VoroCrust, with the vorocrust Python module and libvorocrust
# beside it, where FreeCAD looks for add-ons: MOD_DIR/VoroCrust, MOD_DIR being the argument,
# else $FREECAD_USER_DATA/Mod, else ~/.local/share/FreeCAD/Mod. Installs from build/ (or
# $VOROCRUST_BUILD_DIR), building it first with scripts/build.sh when the module is not built.
#
#   bash scripts/install-freecad-addon.sh [MOD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${VOROCRUST_BUILD_DIR:-build}"
mod_dir="${1:-${FREECAD_USER_DATA:-$HOME/.local/share/FreeCAD}/Mod}"
if ! compgen -G "$build_dir/python/vorocrust/_vorocrust*.so" > /dev/null; then
  if [ "$build_dir" != build ]; then
    echo "install-freecad-addon: the Python module is not built in $build_dir" >&2
    exit 1
  fi
  bash scripts/build.sh
fi
cmake --install "$build_dir" --component freecad --prefix "$mod_dir"
echo "install-freecad-addon: the VoroCrust workbench is in $mod_dir/VoroCrust; restart FreeCAD to load it"
