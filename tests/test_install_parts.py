"""The install split: every part course.py installs is an extra of pyproject.toml whose
packages environment.txt pins, and the hub's image (binder/postBuild) installs one of them
with environment.txt as constraints."""

import os
import re
import sys
import tomllib
from pathlib import Path

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
