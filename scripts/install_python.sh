#!/usr/bin/env bash
# Installs the Python module disk_uv for the system's python3 and Debian's
# Blender (which runs on it), and the Blender add-on:
#   - the Debian packages it needs (scripts/install_dependencies.sh --python),
#   - builds build/python/disk_uv (the package and its compiled part),
#   - copies it to the system's site-packages (/usr/local/lib/python3.X/
#     dist-packages as root, the user's site-packages otherwise),
#   - copies the add-on to Blender's user add-on folder and enables it, and
#     writes build/disk_uv_unwrap.zip (Blender: Preferences > Add-ons > Install).
# Options: --no-blender skips the add-on.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
blender_addon=1
for arg in "$@"; do
  case "$arg" in
    --no-blender) blender_addon=0 ;;
    *) echo "usage: $0 [--no-blender]" >&2; exit 2 ;;
  esac
done
BUILD_TARGETS="_disk_uv disk_uv_python_files" bash "$root/scripts/build.sh" --python \
  -DDISK_SEGMENTATION_BUILD_PYTHON=ON -DDISK_SEGMENTATION_BUILD_EXAMPLES=ON -DDISK_SEGMENTATION_BUILD_TESTS=OFF

python=/usr/bin/python3
if [ "$(id -u)" -eq 0 ]; then
  site=$("$python" -c 'import sysconfig; print(sysconfig.get_path("purelib", "posix_local"))' 2>/dev/null \
         || "$python" -c 'import site; print(site.getsitepackages()[0])')
else
  site=$("$python" -m site --user-site)
fi
mkdir -p "$site"
rm -rf "$site/disk_uv.new"
cp -r "$build/python/disk_uv" "$site/disk_uv.new"
rm -rf "$site/disk_uv"
mv "$site/disk_uv.new" "$site/disk_uv"
(cd / && "$python" -c 'import disk_uv, sys; print("disk_uv installed in", disk_uv.__path__[0])')

"$python" - "$root/python/blender" "$build/disk_uv_unwrap.zip" <<'PY'
import glob, os, sys, zipfile
folder, target = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(target + ".part", "w", zipfile.ZIP_DEFLATED) as z:
    for path in sorted(glob.glob(os.path.join(folder, "disk_uv_unwrap", "*.py"))):
        z.write(path, os.path.relpath(path, folder))
os.replace(target + ".part", target)
print("Blender add-on archive:", target)
PY

if [ "$blender_addon" = 1 ] && command -v blender >/dev/null 2>&1; then
  # With the user's preferences loaded (no --factory-startup), so that
  # saving them keeps everything else the user set.
  if ! output=$(blender -b --python-exit-code 1 --python-expr "
import bpy, addon_utils
bpy.ops.preferences.addon_install(overwrite=True, filepath='$build/disk_uv_unwrap.zip')
bpy.ops.preferences.addon_enable(module='disk_uv_unwrap')
bpy.ops.wm.save_userpref()
import disk_uv, disk_uv_unwrap
assert addon_utils.check('disk_uv_unwrap')[1], 'the add-on is not enabled'
print('Blender add-on installed in', disk_uv_unwrap.__file__, 'and enabled; disk_uv found at', disk_uv.__path__[0])
" 2>&1); then
    echo "$output" >&2
    echo "error: the Blender add-on could not be installed" >&2
    exit 1
  fi
  echo "$output" | grep "add-on installed"
fi
