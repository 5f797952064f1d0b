"""One numbering of the links: every mechanism family (found by ``Mechanism.families()``, not listed by hand) is
numbered by its structure alone, and the drawing, the instantaneous centres and the force model give each link the
same number (each moving link but the blocks once, the frame its own); the design layer's counts of parts and pairs
come from the structure too (with the rollers and locking arcs the kinematic structure leaves out)."""

import importlib
import pkgutil

import matplotlib.pyplot as plt
import numpy as np
import pytest
from examples import designs, example_of
from examples import families as found_families

import mechlab as ml
from mechlab.design import FAMILIES, Specification
from mechlab.design.criteria import counted
from mechlab.draw import draw
from mechlab.errors import SpatialMechanismError, StructureError
from mechlab.kinetostatics.machines import Kinetostatics
from mechlab.kinetostatics.model import model_for
from mechlab.mechanisms.base import FRAME, Mechanism, _still_defined
from mechlab.mechanisms.linkage import LinkageFamily

DEG = np.pi / 180

# Mechanism subclasses that are no family: a mechanism with its loads (drawn as its mechanism); the base of the
# families a dataclass of dimensions builds as a Linkage (a family subclasses it; tests/test_new_family.py)
NOT_FAMILIES = {Kinetostatics, LinkageFamily}
# families whose input is no crank on a frame pivot: no force model (model_for says so, StructureError)
NO_CRANK = {ml.EllipticTrammel}


def families():
    """One example of every family of mechlab, found (``Mechanism.families()``), not listed here."""
    return [example_of(cls) for cls in found_families() if cls.__module__.startswith("mechlab.")]


def mechanism_classes():
    """Every subclass of Mechanism that mechlab defines (all of its modules imported)."""
    for info in pkgutil.walk_packages(ml.__path__, "mechlab."):
        importlib.import_module(info.name)

    def below(cls):
        for sub in cls.__subclasses__():
            yield sub
            yield from below(sub)

    # a class a doctest made in a module's borrowed globals (LinkageFamily's example) is not the module's
    return {c for c in below(Mechanism) if c.__module__.startswith("mechlab.") and _still_defined(c)}


def test_every_family_is_found():
    # a class of mechlab that defines no example() is found by no service: only a base (with subclasses) may lack one
    covered = {type(m) for m in families()}
    missing = {c for c in mechanism_classes() - covered - NOT_FAMILIES if not c.__subclasses__()}
    assert not missing, f"families with no example(): {sorted(c.__name__ for c in missing)}"
    assert ml.Linkage in covered and ml.SixBarIV in covered and ml.TranslatingRollerCam in covered


def _id(m):
    return type(m).__name__


@pytest.mark.parametrize("mech", families(), ids=_id)
def test_drawing_centres_and_forces_number_each_link_alike(mech):
    check_numbering(mech)


def check_numbering(mech):
    """The drawing, the centres and the force model of ``mech`` give each link the same number."""
    st = mech.structure()
    if st.spatial:   # drawn in 3-D; the planar centres and forces refuse it, naming why
        for ask in (lambda: ml.instant_centres(mech, [0.1]), lambda: model_for(mech)):
            with pytest.raises(SpatialMechanismError, match="spatial mechanism"):
                ask()
        return
    phi = float(mech.cycle(7)[2]) + 0.01
    d = draw(mech, phi)
    shown = {part.number: text.get_text() for part, text in zip(d.numbered, d.numbers, strict=False)}
    frame = d.numbers[len(d.numbered)].get_text()
    assert len(shown) == len(d.numbered), f"a link numbered twice: {[p.number for p in d.numbered]}"
    # the centres number the links' labels
    centres = ml.instant_centres(mech, [phi]).structure.links
    label = {k.name: k.label or k.name for k in st.links}
    by_centres = {name: str(centres.index(label[name]) + 1) for name in shown}
    assert shown == by_centres and frame == str(centres.index(FRAME) + 1)
    # every link the centres number is drawn with its number, once; the frame's is the one left
    assert sorted([*shown.values(), frame], key=int) == [str(k) for k in range(1, len(centres) + 1)]
    if type(mech) in NO_CRANK:
        with pytest.raises(StructureError, match="not a crank"):
            model_for(mech)
    else:
        model = model_for(mech)
        assert {name: str(model.number(name)) for name in shown} == shown
        assert str(model.number(FRAME)) == frame
        assert set(model.numbering) == {*shown, FRAME}
    plt.close("all")


def test_a_sketch_numbering_no_link_of_the_structure_is_refused():
    class Renumbered(ml.FourBar):
        def sketch(self, motion):
            sk = super().sketch(motion)
            return type(sk)(tuple(type(p)(p.role, p.at, "lever") if p.number else p for p in sk.parts), sk.pivots)

    with pytest.raises(ml.MechanismError, match=r"numbers \['lever'.*not links of its structure"):
        draw(Renumbered(1, 3, 3, 4), 0.3)
    plt.close("all")


def test_the_numbering_is_the_structures_own():
    # a structure's explicit numbering (Kozhevnikov's for the six-bar: the output 4, link 5 last) reaches all three
    six = ml.SixBarIV.example()
    assert six.structure().numbers() == {"crank": 1, "coupler": 2, "link 3": 3, "output": 4, "link 5": 5, "frame": 6}
    assert model_for(six).numbering == ("crank", "coupler", "link 3", "output", "link 5", FRAME)
    with pytest.raises(ml.MechanismError, match="numbering"):
        type(six.structure())(six.structure().links, (), (), "output", 1.0, numbering=("crank", "crank")).numbers()


def test_design_counts_come_from_the_structure():
    specs = [Specification("index", 0.75, stations=4, inertia=1.0),
             Specification("swing", 50 / 360, amplitude=40 * DEG, max_pressure_angle=60 * DEG),
             Specification("stroke", 1 / 3, amplitude=120.0, mass=6.0, max_size=2000.0),
             Specification("index", 0.5, stations=2, inertia=1.0)]
    seen = {}
    for name, family in FAMILIES.items():
        for spec in specs:
            try:
                design = family(spec)
                # a designed mechanism is of a found family, counted as check_design counts it (the class's own)
                assert type(design.mechanism) in found_families(), name
                assert design.structure == counted(design.mechanism), name
                seen[name] = design.structure
                break
            except ml.MechanismError:
                continue
    # the counts the families carried by hand before, now counted from their structures
    expected = {"external Geneva": (2, 2, 2), "internal Geneva": (2, 2, 2), "spherical Geneva": (2, 2, 2),
                "curved slot": (3, 3, 1),
                "disc cam": (3, 3, 1), "lambda six-bar, type 1 (rocker dwell)": (5, 7, 0),
                "lambda six-bar, type 2 (slider dwell)": (5, 7, 0),
                "lambda six-bar, type 3 (half-turn index)": (5, 7, 0),
                "lambda six-bar, type 5 (translating-slot dwell)": (5, 7, 0)}
    for name, counts in expected.items():
        if name in seen:
            assert (seen[name].parts, seen[name].lower_pairs, seen[name].higher_pairs) == counts, name
    assert {"lambda six-bar, type 1 (rocker dwell)", "external Geneva", "spherical Geneva", "disc cam"} <= set(seen)
    # a six-bar: W = 3·5 - 2·7 = 1 (Chebyshev-Grübler)
    for six in designs():
        c = counted(six)
        assert 3 * c.parts - 2 * c.lower_pairs - c.higher_pairs == 1
