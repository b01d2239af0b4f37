#!/usr/bin/env python3
"""Builds the add-on zip for Blender: Preferences → Add-ons → Install from Disk (or, for
Blender 4.2+, drag it in as an extension; it carries blender_manifest.toml).

    python3 integrations/blender/build_zip.py            # → dist/shenlong_blender-0.1.0.zip
    python3 integrations/blender/build_zip.py --out DIR

The zip holds the package folder `shenlong_blender/` with its Python files and manifest,
nothing else (no caches); entries are sorted and dated 1980-01-01, so the same sources
give the same bytes.
"""

import argparse
import os
import sys
import tomllib
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = os.path.join(HERE, "shenlong_blender")


def build(out_dir: str) -> str:
    with open(os.path.join(PACKAGE, "blender_manifest.toml"), "rb") as f:
        version = tomllib.load(f)["version"]
    os.makedirs(out_dir, exist_ok=True)
    target = os.path.join(out_dir, f"shenlong_blender-{version}.zip")
    files = sorted(
        name
        for name in os.listdir(PACKAGE)
        if name.endswith(".py") or name == "blender_manifest.toml"
    )
    tmp = target + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for name in files:
            info = zipfile.ZipInfo(f"shenlong_blender/{name}", date_time=(1980, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = 0o644 << 16
            with open(os.path.join(PACKAGE, name), "rb") as f:
                z.writestr(info, f.read())
    os.replace(tmp, target)
    return target


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.join(HERE, "..", "..", "dist"), help="output folder")
    args = parser.parse_args()
    print(build(os.path.abspath(args.out)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
