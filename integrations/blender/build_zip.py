#!/usr/bin/env python3
"""Builds the Blender extension (4.2+): drag the zip into Blender, or Preferences → Get
Extensions → Install from Disk. It carries the `shenlong` package as a wheel, which
Blender installs for the add-on, which calls it in Blender's own process.

    (cd python && maturin build --release --out ../dist/wheels)
    python3 integrations/blender/build_zip.py --wheel dist/wheels/shenlong-*.whl
    python3 integrations/blender/build_zip.py --wheel WHEEL --out DIR

The zip holds the add-on's Python files, its manifest (with the `wheels` and `platforms`
of the wheels given) and `wheels/`, nothing else (no caches); entries are sorted and
dated 1980-01-01, so the same sources give the same bytes.
"""

import argparse
import os
import sys
import tomllib
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.join(HERE, "shenlong_blender")


#: A wheel's platform tag → Blender's platform name.
PLATFORMS = (
    ("manylinux", "x86_64", "linux-x64"),
    ("linux", "x86_64", "linux-x64"),
    ("manylinux", "aarch64", "linux-arm64"),
    ("macosx", "arm64", "macos-arm64"),
    ("macosx", "x86_64", "macos-x64"),
    ("win", "amd64", "windows-x64"),
    ("win", "arm64", "windows-arm64"),
)


def platform_of(wheel: str) -> str:
    """Blender's name for the platform a wheel is built for."""
    tag = os.path.basename(wheel)[: -len(".whl")].split("-")[-1].lower()
    for system, machine, name in PLATFORMS:
        if tag.startswith(system) and tag.endswith(machine):
            return name
    raise SystemExit(f"build_zip: the wheel {os.path.basename(wheel)} is for no platform Blender names")


def manifest(wheels: list[str]) -> bytes:
    """The manifest with the wheels and their platforms in place of its `# WHEELS` line."""
    with open(os.path.join(PACKAGE, "blender_manifest.toml"), encoding="utf-8") as f:
        text = f.read()
    names = ", ".join(f'"./wheels/{os.path.basename(w)}"' for w in wheels)
    platforms = ", ".join(f'"{p}"' for p in sorted({platform_of(w) for w in wheels}))
    if "# WHEELS" not in text:
        raise SystemExit("build_zip: blender_manifest.toml has no '# WHEELS' line")
    text = text.replace("# WHEELS", f"wheels = [{names}]\nplatforms = [{platforms}]")
    tomllib.loads(text)  # still a manifest
    return text.encode("utf-8")


def build(out_dir: str, wheels: list[str]) -> str:
    if not wheels:
        raise SystemExit("build_zip: give the shenlong wheel with --wheel (maturin build makes it)")
    for wheel in wheels:
        if not (wheel.endswith(".whl") and os.path.isfile(wheel)):
            raise SystemExit(f"build_zip: {wheel} is not a wheel file")
    with open(os.path.join(PACKAGE, "blender_manifest.toml"), "rb") as f:
        version = tomllib.load(f)["version"]
    os.makedirs(out_dir, exist_ok=True)
    target = os.path.join(out_dir, f"shenlong_blender-{version}.zip")
    entries = {
        name: open(os.path.join(PACKAGE, name), "rb").read()
        for name in os.listdir(PACKAGE)
        if name.endswith(".py")
    }
    entries["blender_manifest.toml"] = manifest(wheels)
    for wheel in wheels:
        with open(wheel, "rb") as f:
            entries[f"wheels/{os.path.basename(wheel)}"] = f.read()
    tmp = target + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for name in sorted(entries):
            info = zipfile.ZipInfo(f"shenlong_blender/{name}", date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            z.writestr(info, entries[name])
    os.replace(tmp, target)
    return target


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.join(HERE, "..", "..", "dist"), help="output folder")
    parser.add_argument("--wheel", action="append", default=[], help="a shenlong wheel to bundle (repeat for platforms)")
    args = parser.parse_args()
    print(build(os.path.abspath(args.out), args.wheel))
    return 0


if __name__ == "__main__":
    sys.exit(main())
