# SPDX-License-Identifier: GPL-3.0-or-later
"""make_wheel.py MODULE.so VERSION OUT_DIR: the compiled module `elastica` as a wheel (PEP 427) for a
Blender Extension's `wheels` list; prints the wheel's path. Blender 4.2+ refuses an Extension that puts a
top-level module into sys.modules itself ("Policy violation with top level module"), and installs the
wheels it lists onto its own path instead. Made with zipfile, so no wheel tool is needed: the module at
the top, and elastica-VERSION.dist-info with METADATA, WHEEL and RECORD (sha256 of each file). The tags
come from the module's name (elastica.cpython-314-x86_64-linux-gnu.so: cp314, linux_x86_64)."""
import base64
import hashlib
import os
import re
import sys
import zipfile


def record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{name},sha256={digest},{len(data)}"


def main(module, version, out_dir):
    base = os.path.basename(module)
    m = re.fullmatch(r"elastica\.cpython-(\d+)-(x86_64|aarch64)-linux-gnu\.so", base)
    if not m:
        sys.exit(f"make_wheel.py: {base} is not a CPython extension module for Linux named elastica")
    python = "cp" + m.group(1)
    platform = "linux_" + m.group(2)
    info = f"elastica-{version}.dist-info"
    files = {
        base: open(module, "rb").read(),
        f"{info}/METADATA": (f"Metadata-Version: 2.1\nName: elastica\nVersion: {version}\n"
                             "Summary: Discrete elastica fairing, hole filling and curvature of triangle meshes\n"
                             "License: GPL-3.0-or-later\n").encode(),
        f"{info}/WHEEL": (f"Wheel-Version: 1.0\nGenerator: elastica make_wheel.py\nRoot-Is-Purelib: false\n"
                          f"Tag: {python}-{python}-{platform}\n").encode(),
    }
    record = "\n".join(record_line(n, d) for n, d in files.items()) + f"\n{info}/RECORD,,\n"
    files[f"{info}/RECORD"] = record.encode()
    wheel = os.path.join(out_dir, f"elastica-{version}-{python}-{python}-{platform}.whl")
    os.makedirs(out_dir, exist_ok=True)
    with zipfile.ZipFile(wheel, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            entry = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
            entry.external_attr = (0o755 if name.endswith(".so") else 0o644) << 16
            z.writestr(entry, data, zipfile.ZIP_DEFLATED)
    print(wheel)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
