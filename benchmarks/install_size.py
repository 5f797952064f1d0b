"""The student's install: time of `python course.py venv lab` and the venv's size, from a
fresh clone of HEAD with an empty pip cache (PyPI is still reached over the network), and
what each installed distribution takes.

    python benchmarks/install_size.py [--python /usr/bin/python3] [--part lab] [--top 30]
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# run in the measured venv: each distribution's files as its RECORD lists them, in du's blocks
PER_DISTRIBUTION = """
import importlib.metadata as m, json, os
rows = []
for d in m.distributions():
    size = 0
    for f in d.files or []:
        try:
            size += os.lstat(f.locate()).st_blocks * 512
        except FileNotFoundError:
            pass
    rows.append((size, d.metadata["Name"], d.version, len(d.files or [])))
print(json.dumps(sorted(rows, reverse=True)))
"""


def size_mib(path: Path) -> float:
    """Disk usage as `du -sm` counts it (the issue's 969 MB is that figure)."""
    return sum(p.lstat().st_blocks for p in [path, *path.rglob("*")]) * 512 / 2**20


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--part", default="lab")
    parser.add_argument("--top", type=int, default=30, help="how many distributions to list, largest first")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="mechlab-install-") as tmp:
        clone = Path(tmp) / "course"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        env = {**os.environ, "PIP_CACHE_DIR": str(Path(tmp) / "pip-cache")}
        start = time.perf_counter()
        subprocess.run([args.python, "course.py", "venv", args.part], cwd=clone, env=env, check=True)
        seconds = time.perf_counter() - start
        venv = clone / ".venv"
        rows = json.loads(subprocess.run([str(venv / "bin" / "python"), "-c", PER_DISTRIBUTION], check=True,
                                         capture_output=True, text=True).stdout)
        listed = sum(size for size, *_ in rows) / 2**20
        print(f"part {args.part!r} with {args.python}: {seconds:.0f} s, venv {size_mib(venv):.0f} MiB (du -sm), "
              f"{len(rows)} distributions holding {listed:.0f} MiB (the rest: folders and the venv's own files)")
        for size, name, version, files in rows[:args.top]:
            print(f"{size / 2**20:8.1f} MiB  {name}=={version}  ({files} files)")


if __name__ == "__main__":
    main()
