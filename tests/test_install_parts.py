"""The install split: every part course.py installs is an extra of pyproject.toml whose
packages environment.txt pins, and the hub's image (binder/postBuild) installs one of them
with environment.txt as constraints, on a Python the pins install on; where repo2docker is
installed, its rendering of binder/ is checked too."""

import os
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
import course  # noqa: E402  (the script at the repository's root)

EXTRAS = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]


def name(requirement: str) -> str:
    return course.canonical(re.match(r"[A-Za-z0-9_.-]+", requirement)[0])


def test_every_part_but_all_is_an_extra_and_contains_what_its_extras_include():
    assert set(course.PARTS) - {"all"} == set(EXTRAS)
    for part, extras in EXTRAS.items():
        for req in extras:
            if name(req) == "mechlab":  # mechlab[lab] and the like: the part includes those parts
                included = set(re.search(r"\[(.*)\]", req)[1].split(","))
                assert included <= course.PARTS[part], (part, included)


def test_every_package_of_every_part_is_pinned():
    pinned = course.pins()
    unpinned = {name(req) for reqs in EXTRAS.values() for req in reqs} - set(pinned) - {"mechlab"}
    assert not unpinned, f"not in environment.txt: {unpinned}"


def test_the_hub_image_installs_a_part_with_the_pins_as_constraints():
    post_build = ROOT / "binder" / "postBuild"
    assert os.access(post_build, os.X_OK)
    install = [line for line in post_build.read_text().splitlines() if "pip install" in line]
    assert len(install) == 1 and "-c environment.txt" in install[0]
    part = re.search(r'-e "\.\[(\w+)\]"', install[0])[1]
    assert part in EXTRAS and "lab" in course.PARTS[part]


def test_the_hub_image_uses_a_python_the_pins_install_on():
    runtime = (ROOT / "binder" / "runtime.txt").read_text().strip()
    version = tuple(int(n) for n in re.fullmatch(r"python-(\d+)\.(\d+)", runtime).groups())
    assert version >= course.MIN_PYTHON, runtime


REPO2DOCKER = shutil.which(os.environ.get("REPO2DOCKER", "repo2docker"))


@pytest.mark.skipif(not REPO2DOCKER, reason="repo2docker is not installed (set REPO2DOCKER to its executable)")
def test_repo2docker_renders_an_image_that_runs_the_post_build_on_the_runtime_python(tmp_path):
    """repo2docker's own reading of binder/ (--no-build: the Dockerfile only, no Docker engine needed)."""
    clone = tmp_path / "course"
    subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
    done = subprocess.run([REPO2DOCKER, "--no-build", "--debug", "--user-id", "1000", "--user-name", "jovyan",
                           str(clone)], check=False, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    out = done.stdout + done.stderr
    python = (ROOT / "binder" / "runtime.txt").read_text().strip().removeprefix("python-")
    assert f"Building conda environment for python={python}" in out
    copy, post_build = out.index("src/ ${REPO_DIR}/"), out.index("RUN ./binder/postBuild")
    assert copy < post_build  # the post-build step installs from the copied repository


def fake_download(calls, *, fails=False):
    """subprocess.run standing in for `pip download`: records the command and writes the wheel it names."""
    def run(command, **kwargs):
        calls.append(command)
        if not fails:
            dist, version = command[-1].split("==")
            (Path(command[command.index("-d") + 1]) / f"{dist}-{version}-py3-none-any.whl").touch()
        return subprocess.CompletedProcess(command, 1 if fails else 0)
    return run


@pytest.mark.parametrize("part", sorted(course.PARTS))
def test_every_part_installs_ezdxf_from_its_pure_wheel_at_its_pin(part, tmp_path, monkeypatch):
    calls = []
    monkeypatch.setattr(course.subprocess, "run", fake_download(calls))
    wheels = course.pure_wheels(Path("venv/bin/python"), tmp_path)
    pin = course.pins()["ezdxf"]
    download = calls[0]
    assert download[1:4] == ["-m", "pip", "download"] and download[-1] == f"ezdxf=={pin}"
    for option, value in (("--platform", "any"), ("--implementation", "py"), ("--only-binary", None)):
        assert any(arg == option or arg.startswith(f"{option}=") for arg in download), option
        if value:
            assert download[download.index(option) + 1] == value
    assert wheels == [tmp_path / f"ezdxf-{pin}-py3-none-any.whl"]
    command = course.install_command(["pip", "install"], part, wheels)
    assert str(wheels[0]) in command  # pip takes this file for the ezdxf requirement
    assert "environment.txt" in command and command[command.index("environment.txt") - 1] in ("-c", "-r")


def test_a_failed_download_stops_with_a_clear_message(tmp_path, monkeypatch):
    monkeypatch.setattr(course.subprocess, "run", fake_download([], fails=True))
    with pytest.raises(SystemExit, match=r"could not download ezdxf==[\d.]+ .*network"):
        course.pure_wheels(Path("venv/bin/python"), tmp_path)
