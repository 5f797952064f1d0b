"""A family added in this file alone, with no other edit anywhere: a crank-rocker four-bar whose rocker's arm drives
a ram on a vertical guide (crank, RRR dyad, RRP dyad: six links, found nowhere in mechlab). Defined here as a
dataclass of its dimensions that builds itself from a crank and Assur groups, it gets from mechlab's services, each
checked with numbers: its motion (against a closed form written here, differentiated by mpmath at 40 digits, to
1e-10), its drawing and one numbering, its instantaneous centres (Kennedy's theorem, the velocities they give), its
force model (the balancing torque by virtual power), validation (named errors for a bad instance), a design-layer
count (equal to the mobility count) and fuzz coverage (the fuzz test finds it)."""

import re
from dataclasses import dataclass, replace

import matplotlib.pyplot as plt
import mpmath as mp
import numpy as np
import pytest
import test_fuzz
from examples import families
from test_builder import paths
from test_numbering import check_numbering
from test_structures import test_each_pair_joins_its_links_where_the_motion_puts_them as pairs_agree
from test_structures import test_mobility_is_one_and_each_group_zero as groups_are_assur

import mechlab as ml
from mechlab import design as D
from mechlab.design.criteria import counted
from mechlab.draw import animate, draw
from mechlab.errors import AssemblyError, DimensionError
from mechlab.kinetostatics.model import Force, model_for
from mechlab.kinetostatics.solve import solve
from mechlab.mechanisms.linkage import LinkageFamily
from mechlab.validate import Coordinate, Length


@dataclass(frozen=True)
class RockerRam(LinkageFamily):
    """A crank-rocker O-A-B-E (pivots O and E on the x axis) whose rocker carries, ``arm`` from E along E→B, the pin
    C of a rod C-D; the ram D slides on the vertical guide x = ``guide_x``, above the rod's foot."""

    crank: Length
    coupler: Length
    rocker: Length
    ground: Length
    arm: Length
    rod: Length
    guide_x: Coordinate

    title = "rocker-driven ram"

    def linkage(self) -> ml.Linkage:
        return (ml.Linkage({"O": (0.0, 0.0), "E": (self.ground, 0.0), "G": (self.guide_x, 0.0)},
                           ml.Crank("O", "A", self.crank))
                .rrr("A", "E", "B", self.coupler, self.rocker, links=("coupler", "rocker"))
                .point("C", "rocker", (self.arm, 0.0))
                .rrp("C", "D", self.rod, ("G", np.pi / 2), links=("rod", "ram")))

    @classmethod
    def example(cls) -> "RockerRam":
        return cls(1.0, 3.2, 2.6, 3.5, 3.6, 2.5, 2.0)


RAM = RockerRam.example()
PHI = np.linspace(0.0, 2 * np.pi, 37)[:-1] + 0.013


def closed(m: RockerRam):
    """B, C, D (x, y each) at a crank angle, written here from the geometry alone (not mechlab's solvers)."""
    def at(phi):
        A = (m.crank * mp.cos(phi), m.crank * mp.sin(phi))
        # B on the circles |B - A| = coupler, |B - E| = rocker, left of A→E (the linkage's assembly +1)
        dx, dy = m.ground - A[0], -A[1]
        d = mp.sqrt(dx**2 + dy**2)
        along = (m.coupler**2 - m.rocker**2 + d**2) / (2 * d)
        h = mp.sqrt(m.coupler**2 - along**2)
        B = (A[0] + (along * dx - h * dy) / d, A[1] + (along * dy + h * dx) / d)
        C = (m.ground + m.arm * (B[0] - m.ground) / m.rocker, m.arm * B[1] / m.rocker)
        D = (mp.mpf(m.guide_x), C[1] + mp.sqrt(m.rod**2 - (m.guide_x - C[0]) ** 2))
        return (*B, *C, *D)
    return at


@pytest.fixture(scope="module")
def want():
    return paths(closed(RAM), PHI)


def test_it_is_found_as_a_family():
    assert RockerRam in ml.Mechanism.families() and RockerRam in families()
    assert RockerRam.__module__ == __name__ and RockerRam.title == "rocker-driven ram"
    assert RAM.can_turn and RAM.output == "position"


def test_motion_against_the_closed_form(want):
    mo = RAM.motion(PHI)
    for k, joint in enumerate("BCD"):
        for got, w in zip((mo.points[joint].p, mo.points[joint].d, mo.points[joint].dd), want, strict=False):
            assert np.abs(got - w[:, 2 * k:2 * k + 2]).max() <= 1e-10 * max(1.0, np.abs(w).max()), joint
    # the output: the ram's height above G, with its analogs
    for got, w in zip((mo.s, mo.ds, mo.dds), want, strict=False):
        assert np.abs(got - w[:, 5]).max() <= 1e-10 * max(1.0, np.abs(w[:, 5]).max())
    assert float(np.ptp(RAM.motion(RAM.turn(721)).s)) > 1.0   # a real stroke, not a ram standing still


def test_its_structure_agrees_with_its_motion():
    pairs_agree(RAM)   # each pair joins its two links where the motion puts them
    groups_are_assur(RAM)   # W = 1, each group W = 0
    assert RAM.structure().groups == (("rod", "ram"), ("coupler", "rocker"))   # output first


def test_drawing_and_one_numbering():
    check_numbering(RAM)   # drawing, centres and force model give each link the same number
    d = draw(RAM, 0.4)
    assert [t.get_text() for t in d.numbers if t.get_visible()] == ["1", "2", "3", "4", "5", "6"]
    assert RAM.structure().numbers() == {"crank": 1, "coupler": 2, "rocker": 3, "rod": 4, "ram": 5, "frame": 6}
    # animated with its law: the page describes it by its class name, its joints and the stroke of its frames
    alt = re.search(r'<img alt="([^"]+)"', animate(RAM, n=6, law=True).to_jshtml()).group(1)
    assert "rocker ram with joints O, E, G, A, B, C, D" in alt and "Animation of 6 frames" in alt
    plt.close("all")


def test_centres_obey_kennedy_and_give_the_velocities(want):
    ic = ml.instant_centres(RAM, PHI)
    assert ic.collinearity() < 1e-9   # every three links' centres on one line
    # the velocities the centres give (Kennedy's ratio theorem) are the closed form's analogs
    assert np.abs(ic.output_analog() - want[1][:, 5]).max() < 1e-9
    assert np.abs(ic.velocity_analog("coupler", want[0][:, 0:2]) - want[1][:, 0:2]).max() < 1e-9
    assert np.abs(ic.velocity_analog("rod", want[0][:, 2:4]) - want[1][:, 2:4]).max() < 1e-9
    # the centres from the links' twists (the other method) are the same points
    by_twists = ml.instant_centres(RAM, PHI, method="velocity")
    for a, b in (("coupler", "frame"), ("rod", "frame"), ("crank", "ram")):
        P, Q = ic(a, b).h, by_twists(a, b).h
        finite = np.abs(P[:, 2]) > 1e-9
        assert np.abs(P[finite, :2] / P[finite, 2:] - Q[finite, :2] / Q[finite, 2:]).max() < 1e-8


def test_forces_balance_by_virtual_power(want):
    # 100 N down on the ram, massless links: M_b·ω1 + F·v_D = 0, so M_b = 100·y_D′ (from the closed form)
    res = solve(model_for(RAM), RAM.motion(PHI), [Force("ram", "D", (0.0, -100.0))], omega1=0.0, gravity=(0.0, 0.0))
    res.verify()
    assert np.abs(res.torque - 100.0 * want[1][:, 5]).max() < 1e-9 * 100 * np.abs(want[1][:, 5]).max()
    # with a heavy rocker turning at 8 rad/s the groups' torque still equals the power balance's (verify: 1e-9)
    moving = solve(model_for(RAM).with_body("rocker", mass=2.0), RAM.motion(PHI), [Force("ram", "D", (0.0, -100.0))],
                   omega1=8.0)
    moving.verify()
    assert np.abs(moving.torque - res.torque).max() > 1.0   # the inertia shows: not the static torque again


def test_validation_names_what_is_wrong():
    with pytest.raises(DimensionError, match="rod must be > 0, got -1"):
        replace(RAM, rod=-1.0)
    with pytest.raises(DimensionError, match="guide_x must be finite, got nan"):
        replace(RAM, guide_x=np.nan)
    # the ram's group (an Assur dyad) cannot reach its guide at any crank angle: refused where it is made
    with pytest.raises(AssemblyError, match=r"RRP group \(rod, ram\) cannot close .* rod's length 0.3"):
        replace(RAM, rod=0.3, guide_x=4.5)


def test_design_layer_counts_equal_the_mobility():
    c = counted(RAM)
    assert (c.parts, c.lower_pairs, c.higher_pairs) == (5, 7, 0)
    assert 3 * c.parts - 2 * c.lower_pairs - c.higher_pairs == RAM.structure().mobility() == 1
    spec = D.Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0, max_size=2000.0)
    report = D.check_design(spec, RAM, scale=40.0)
    assert report.criteria.structure == c and not report.met   # judged (no dwell: it misses), counted alike


def test_the_fuzz_finds_and_fuzzes_it():
    assert test_fuzz.case_name(RockerRam) not in test_fuzz.CASES   # no case written for it anywhere
    test_fuzz.fuzz_family(RockerRam, examples=25)   # what test_every_family_found_is_fuzzed runs for it
