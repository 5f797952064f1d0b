"""The student's install: time of `python course.py venv lab` and the venv's size, from a
fresh clone of HEAD with an empty pip cache (PyPI is still reached over the network).

    python benchmarks/install_size.py [--python /usr/bin/python3] [--part lab]
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def size_mib(path: Path) -> float:
    """Disk usage as `du -sm` counts it (the issue's 969 MB is that figure)."""
    return sum(p.lstat().st_blocks for p in [path, *path.rglob("*")]) * 512 / 2**20


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--python", default=sys.executable)
    parser.add_argument("--part", default="lab")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="mechlab-install-") as tmp:
        clone = Path(tmp) / "course"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        env = {**os.environ, "PIP_CACHE_DIR": str(Path(tmp) / "pip-cache")}
        start = time.perf_counter()
        subprocess.run([args.python, "course.py", "venv", args.part], cwd=clone, env=env, check=True)
        seconds = time.perf_counter() - start
        venv = clone / ".venv"
        print(f"part {args.part!r} with {args.python}: {seconds:.0f} s, venv {size_mib(venv):.0f} MiB (du -sm)")


if __name__ == "__main__":
    main()
