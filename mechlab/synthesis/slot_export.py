"""The designed slot and the disc cams' profiles for manufacture: centre lines, flanks, CSV and DXF.

A roller of radius ρ on the crank pin runs between two flanks, the offsets of the slot's
centre line by ±ρ along its normal (link frame, origin at the link pivot B, x axis the
link's reference line: the frame of :class:`mechlab.synthesis.dwell_slot.DwellSlotMechanism`). An
offset is a faithful flank only while ρ stays below the centre line's radius of
curvature; where 1/|κ| ≤ ρ the flank on the concave side folds over (the cutter
would undercut it), so :func:`check_roller` refuses such a roller. The cubic transition
of Zinchenko et al. (2013) (21), (23) has κ ∝ 1/φ towards the slot's ends, so no roller of positive
radius reproduces its centre line there exactly; the quintic and sextic laws keep κ bounded.

The slot's ends (where the pin turns back, φ = 0 and π) are closed by half circles of
radius ρ. The DXF (written with ezdxf, units mm) has layers ``CENTRE`` (the centre line,
an LWPOLYLINE), ``DWELL`` (the dwell part of the centre line as an exact ARC of radius
l_OA about the link-frame image of O), ``FLANKS`` (two LWPOLYLINEs and the two end ARCs).

A disc cam (:mod:`mechlab.mechanisms.cam`) is exported in its own frame (O at the origin, the
position at φ = 0): :func:`write_cam_csv` and :func:`write_cam_dxf` with layers ``PROFILE`` (the
machined surface, a closed LWPOLYLINE), ``PITCH`` (the roller centre's path) and ``BASE`` (the
base circle). Both refuse an undercut profile (:class:`~mechlab.mechanisms.cam.CamUndercutError`).
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path
from typing import Annotated, Any

import numpy as np

from ..errors import DimensionError, SlotUndercutError
from ..mechanisms.cam import OscillatingRollerCam, TranslatingRollerCam
from ..validate import FilePath, Spec, count, length, validated
from ..validate import mechanism as mechanism_of
from .dwell_slot import DwellSlotMechanism


@dataclass(frozen=True)
class SlotProfile:
    """Sampled slot in the link frame: crank angles φ ∈ [0, π] (the pin's positions), the
    distance S from B, centre line, unit normals, curvature κ, and the flanks at ±ρ."""

    phi: np.ndarray
    S: np.ndarray
    centre: np.ndarray
    normal: np.ndarray
    curvature: np.ndarray
    roller_radius: float

    @property
    def left(self) -> np.ndarray:
        """Flank on the side of +normal (normal = tangent turned +90°, tangent towards B)."""
        return self.centre + self.roller_radius * self.normal

    @property
    def right(self) -> np.ndarray:
        return self.centre - self.roller_radius * self.normal


def _grid(n: int) -> np.ndarray:
    # crank angles over the half turn: the pin passes each slot point once
    return np.linspace(0.0, np.pi, n)


def min_radius_of_curvature(mechanism, n: int = 2001) -> tuple[float, float]:
    """(smallest radius of curvature of the centre line, crank angle φ where it occurs),
    on a grid over [0, π] refined logarithmically towards both ends (down to 1e-6 rad)."""
    ends = np.logspace(-6, -1, 41)
    phi = np.unique(np.concatenate([_grid(n), ends, np.pi - ends]))
    k = np.abs(mechanism.law.curvature(phi))
    i = int(np.argmax(k))
    return float(1.0 / k[i]), float(phi[i])


def check_roller(mechanism, roller_radius: float) -> None:
    """SlotUndercutError if ρ ≥ the centre line's smallest radius of curvature."""
    rmin, where = min_radius_of_curvature(mechanism)
    if roller_radius >= rmin:
        law = mechanism.law
        hint = (" (the cubic transition makes the curvature grow like 1/φ at the slot's ends: use the "
                "'quintic' law)" if law.transition == "cubic" else "")
        raise SlotUndercutError(
            f"roller radius {roller_radius:g} ≥ the slot's smallest radius of curvature {rmin:.4g} "
            f"(at φ = {np.degrees(where):.3g}°): the flank on the concave side would fold over{hint}")


# the dwell mechanism, the roller (None: the mechanism's own), the samples over [0, π]
Designed = Annotated[Any, mechanism_of(DwellSlotMechanism)]
Roller = Annotated[float | None, length(zero=True, optional=True, error=SlotUndercutError)]
HalfTurnSamples = Annotated[int, count(2)]
DiscCam = Annotated[Any, mechanism_of((TranslatingRollerCam, OscillatingRollerCam))]


@validated
def slot_profile(mechanism: Designed, roller_radius: Roller = None, n: HalfTurnSamples = 721) -> SlotProfile:
    """The slot of a :class:`~mechlab.synthesis.dwell_slot.DwellSlotMechanism` sampled at n crank angles
    over [0, π], taken from the curve the solver uses, with flanks at ±ρ.

    Parameters
    ----------
    mechanism : DwellSlotMechanism
        The designed curved-slot dwell mechanism (lengths in mm).
    roller_radius : float, optional
        ρ (mm, ≥ 0); by default the mechanism's own; 0 gives no flanks.
    n : int
        Crank angles over [0, π], ≥ 2 (default 721).

    Returns
    -------
    SlotProfile
        φ, the distance S from B, the centre line, unit normals, curvature κ and the flanks
        ``left``, ``right`` (link frame, mm).

    Raises
    ------
    TypeError
        ``mechanism`` is not a DwellSlotMechanism.
    SlotUndercutError
        ρ is negative, or not below the centre line's smallest radius of curvature.
    DimensionError
        ``n`` is not an integer ≥ 2.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> slot = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), pivot_distance=80.0,
    ...                             transition="quintic", roller_radius=2.0)
    >>> profile = ml.slot_profile(slot, n=5)
    >>> np.round(profile.S, 3).tolist()
    [120.0, 111.917, 89.443, 58.945, 40.0]
    """
    rho = mechanism.roller_radius if roller_radius is None else roller_radius
    if rho > 0:
        check_roller(mechanism, rho)
    phi = _grid(n)
    S = mechanism.law.S(phi)[0]
    c = mechanism.link.slot.evaluate(S)
    t = -c.d / np.hypot(*c.d.T)[:, None]   # towards B, i.e. along the pin's path for φ: 0 → π
    normal = np.stack([-t[:, 1], t[:, 0]], axis=-1)
    return SlotProfile(phi, S, c.p, normal, mechanism.law.curvature(phi), rho)


@validated
def write_csv(mechanism: Designed, path: Annotated[Any, Spec("path", optional=True)] = None,
              roller_radius: Roller = None, n: HalfTurnSamples = 721) -> str:
    """The slot as CSV (columns phi_deg, S, x, y, x_left, y_left, x_right, y_right, curvature).

    Parameters
    ----------
    mechanism : DwellSlotMechanism
        The designed curved-slot dwell mechanism (lengths in mm).
    path : str or path-like, optional
        File to write; nothing is written when None.
    roller_radius : float, optional
        ρ (mm, ≥ 0); by default the mechanism's own; 0 gives no flanks.
    n : int
        Crank angles over [0, π], ≥ 2 (default 721).

    Returns
    -------
    str
        The CSV text, full precision.

    Raises
    ------
    TypeError
        ``mechanism`` is not a DwellSlotMechanism.
    SlotUndercutError
        ρ is negative, or not below the centre line's smallest radius of curvature.
    DimensionError
        ``path`` is not a path, or ``n`` is not an integer ≥ 2.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> slot = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), pivot_distance=80.0,
    ...                             transition="quintic", roller_radius=2.0)
    >>> ml.write_csv(slot, n=5).splitlines()[1].split(",")[:3]
    ['0.0', '120.0', '120.0']
    """
    prof = slot_profile(mechanism, roller_radius, n)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["phi_deg", "S", "x", "y", "x_left", "y_left", "x_right", "y_right", "curvature"])
    L, R = prof.left, prof.right
    for i in range(len(prof.phi)):
        w.writerow([repr(float(v)) for v in (np.degrees(prof.phi[i]), prof.S[i], *prof.centre[i], *L[i], *R[i],
                                              prof.curvature[i])])
    text = buf.getvalue()
    if path is not None:
        Path(path).write_text(text)
    return text


@dataclass(frozen=True, eq=False)
class Columns:
    """The columns of a CSV file read back (:func:`read_csv`): ``names`` in the file's order and
    ``columns["x"]`` the column "x" as a float array."""

    names: tuple[str, ...]
    values: tuple[np.ndarray, ...]

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.names:
            raise KeyError(f"no column {name!r}; the file has {', '.join(self.names)}")
        return self.values[self.names.index(name)]


@validated
def read_csv(path_or_text: FilePath) -> Columns:
    """Columns of a CSV written by :func:`write_csv` or :func:`write_cam_csv` as float arrays.

    Parameters
    ----------
    path_or_text : str or path-like
        A file's path, or the CSV text itself (it holds a line break).

    Returns
    -------
    Columns
        The header's ``names``; ``columns["x"]`` is the column "x" as a float array.

    Raises
    ------
    DimensionError
        A missing file, or text that is not a table of finite numbers under one header row.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> slot = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), pivot_distance=80.0,
    ...                             transition="quintic", roller_radius=2.0)
    >>> columns = ml.read_csv(ml.write_csv(slot, n=5))
    >>> np.round(columns["S"], 3).tolist()
    [120.0, 111.917, 89.443, 58.945, 40.0]
    """
    text = str(path_or_text)
    if "\n" not in text:
        if not Path(text).is_file():
            raise DimensionError(f"path_or_text = {text!r} is neither a file nor CSV text (no line break)")
        text = Path(text).read_text()
    rows = list(csv.reader(io.StringIO(text)))
    try:
        head, body = rows[0], np.array(rows[1:], dtype=float)
    except (IndexError, ValueError) as err:
        raise DimensionError(f"path_or_text holds no table of numbers under one header row: {err}") from None
    if body.ndim != 2 or body.shape[1] != len(head) or not np.all(np.isfinite(body)):
        raise DimensionError(f"path_or_text must hold {len(head)} finite numbers a row under its header "
                             f"{', '.join(head)}")
    return Columns(tuple(head), tuple(body[:, j] for j in range(len(head))))


def _angle_deg(v) -> float:
    return float(np.degrees(np.arctan2(v[1], v[0])))


@validated
def write_dxf(mechanism: Designed, path: FilePath, roller_radius: Roller = None, n: HalfTurnSamples = 721):
    """Write the slot as DXF (R2010, units mm) with ezdxf: layers CENTRE, DWELL and FLANKS.

    Parameters
    ----------
    mechanism : DwellSlotMechanism
        The designed curved-slot dwell mechanism (lengths in mm).
    path : str or path-like
        The file to write.
    roller_radius : float, optional
        ρ (mm, ≥ 0); by default the mechanism's own; 0 gives no flanks.
    n : int
        Crank angles over [0, π], ≥ 2 (default 721).

    Returns
    -------
    ezdxf.document.Drawing
        The document written.

    Raises
    ------
    TypeError
        ``mechanism`` is not a DwellSlotMechanism.
    SlotUndercutError
        ρ is negative, or not below the centre line's smallest radius of curvature.
    DimensionError
        ``path`` is not a path, or ``n`` is not an integer ≥ 2.

    Examples
    --------
    >>> import os, tempfile
    >>> import numpy as np
    >>> import mechlab as ml
    >>> slot = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), pivot_distance=80.0,
    ...                             transition="quintic", roller_radius=2.0)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     doc = ml.write_dxf(slot, os.path.join(folder, "slot.dxf"), n=50)
    >>> sorted({entity.dxf.layer for entity in doc.modelspace()})
    ['CENTRE', 'DWELL', 'FLANKS']
    """
    import ezdxf

    prof = slot_profile(mechanism, roller_radius, n)
    doc = ezdxf.new("R2010", units=4)
    for name, color in (("CENTRE", 1), ("DWELL", 3), ("FLANKS", 5)):
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    msp.add_lwpolyline(prof.centre.tolist(), dxfattribs={"layer": "CENTRE"})
    law = mechanism.law
    O = law.centre_in_link()
    arc = mechanism.dwell_points(3)
    a1, a2 = _angle_deg(arc[0] - O), _angle_deg(arc[-1] - O)
    start, end = (a1, a2) if np.mod(a2 - a1, 360.0) < 180.0 else (a2, a1)   # ezdxf arcs run counter-clockwise
    msp.add_arc(O.tolist(), law.crank, start, end, dxfattribs={"layer": "DWELL"})
    rho = prof.roller_radius
    if rho > 0:
        msp.add_lwpolyline(prof.left.tolist(), dxfattribs={"layer": "FLANKS"})
        msp.add_lwpolyline(prof.right.tolist(), dxfattribs={"layer": "FLANKS"})
        # end caps: half circles from the right flank to the left one around each end,
        # on the side away from the slot (outward tangent)
        for i, outward in ((0, prof.centre[0] - prof.centre[1]), (-1, prof.centre[-1] - prof.centre[-2])):
            nrm = prof.normal[i]
            a_left = _angle_deg(nrm)
            a_right = _angle_deg(-nrm)
            mid = np.radians(a_left + 90.0)
            if np.dot([np.cos(mid), np.sin(mid)], outward) > 0:
                start, end = a_left, a_right
            else:
                start, end = a_right, a_left
            msp.add_arc(prof.centre[i].tolist(), rho, start, end, dxfattribs={"layer": "FLANKS"})
    doc.saveas(str(path))
    return doc


@dataclass(frozen=True, eq=False)
class SlotDrawing:
    """A slot's DXF read back (:func:`read_dxf`): the centre line (n, 2), the dwell arc's centre and
    radius, and the flanks' polylines (none for a slot written without a roller)."""

    centre: np.ndarray
    dwell_centre: np.ndarray
    dwell_radius: float
    flanks: tuple[np.ndarray, ...]


@validated
def read_dxf(path: FilePath) -> SlotDrawing:
    """The layers of a slot DXF written by :func:`write_dxf`, read with ezdxf.

    Parameters
    ----------
    path : str or path-like
        A DXF file written by :func:`write_dxf`.

    Returns
    -------
    SlotDrawing
        The ``CENTRE`` polyline, the ``DWELL`` arc's centre and radius, and the ``FLANKS`` polylines.

    Raises
    ------
    DimensionError
        A missing or unreadable file, or one without one CENTRE polyline and one DWELL arc.

    Examples
    --------
    >>> import os, tempfile
    >>> import numpy as np
    >>> import mechlab as ml
    >>> slot = ml.curved_slot_dwell(0.5, np.radians(60), np.radians(150), pivot_distance=80.0,
    ...                             transition="quintic", roller_radius=2.0)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     _ = ml.write_dxf(slot, os.path.join(folder, "slot.dxf"), n=50)
    ...     drawing = ml.read_dxf(os.path.join(folder, "slot.dxf"))
    >>> drawing.dwell_radius, len(drawing.flanks)  # the arc of radius l_OA = 0.5 · 80 mm
    (40.0, 2)
    """
    import ezdxf

    where = repr(str(path))
    if not Path(str(path)).is_file():
        raise DimensionError(f"path = {where} is not a file: write it with write_dxf")
    try:
        msp = ezdxf.readfile(str(path)).modelspace()
    except (OSError, ezdxf.DXFError) as err:
        raise DimensionError(f"path = {where} is not a readable DXF: {err}") from None

    def polylines(layer):
        return [np.array([p[:2] for p in e.get_points()]) for e in msp.query(f'LWPOLYLINE[layer=="{layer}"]')]

    centre, arcs = polylines("CENTRE"), msp.query('ARC[layer=="DWELL"]')
    if len(centre) != 1 or len(arcs) != 1:
        raise DimensionError(f"path = {where} holds {len(centre)} polylines on layer CENTRE and {len(arcs)} arcs "
                             f"on layer DWELL, not one of each: not a slot written by write_dxf")
    (arc,) = arcs
    return SlotDrawing(centre[0], np.array([arc.dxf.center.x, arc.dxf.center.y]), float(arc.dxf.radius),
                       tuple(polylines("FLANKS")))


@validated
def write_cam_csv(cam: DiscCam, path: Annotated[Any, Spec("path", optional=True)] = None,
                  n: HalfTurnSamples = 721) -> str:
    """A disc cam's profile as CSV (columns theta_deg, x_pitch, y_pitch, x, y, nx, ny, curvature,
    pressure_angle_deg; x, y the surface, n the outward normal, curvature the pitch curve's), at n
    cam angles over one turn.

    Parameters
    ----------
    cam : TranslatingRollerCam or OscillatingRollerCam
        The disc cam (lengths in mm).
    path : str or path-like, optional
        File to write; nothing is written when None.
    n : int
        Cam angles over one turn, ≥ 2 (default 721).

    Returns
    -------
    str
        The CSV text, full precision.

    Raises
    ------
    TypeError
        ``cam`` is not a disc cam.
    CamUndercutError
        The profile is undercut (the roller too large for the pitch curve).
    DimensionError
        ``path`` is not a path, or ``n`` is not an integer ≥ 2.

    Examples
    --------
    >>> import numpy as np
    >>> import mechlab as ml
    >>> cam = ml.TranslatingRollerCam(ml.CamProgramme(10.0, np.pi / 2, np.pi / 2), 40.0, 10.0)
    >>> ml.write_cam_csv(cam, n=5).splitlines()[1].split(",")[:5]
    ['0.0', '0.0', '50.0', '0.0', '40.0']
    """
    prof = cam.profile(n)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["theta_deg", "x_pitch", "y_pitch", "x", "y", "nx", "ny", "curvature", "pressure_angle_deg"])
    cols = np.column_stack([np.degrees(prof.theta), prof.pitch, prof.surface, prof.normal, prof.curvature,
                            np.degrees(prof.pressure_angle)])
    for row in cols:
        w.writerow([repr(float(v)) for v in row])
    text = buf.getvalue()
    if path is not None:
        Path(path).write_text(text)
    return text


@validated
def write_cam_dxf(cam: DiscCam, path: FilePath, n: HalfTurnSamples = 721):
    """Write a disc cam as DXF (R2010, units mm) with ezdxf: the closed profile, the pitch curve and
    the base circle, at n cam angles over one turn.

    Parameters
    ----------
    cam : TranslatingRollerCam or OscillatingRollerCam
        The disc cam (lengths in mm).
    path : str or path-like
        The file to write.
    n : int
        Cam angles over one turn, ≥ 2 (default 721).

    Returns
    -------
    ezdxf.document.Drawing
        The document written, layers PROFILE, PITCH and BASE.

    Raises
    ------
    TypeError
        ``cam`` is not a disc cam.
    CamUndercutError
        The profile is undercut.
    DimensionError
        ``path`` is not a path, or ``n`` is not an integer ≥ 2.

    Examples
    --------
    >>> import os, tempfile
    >>> import numpy as np
    >>> import mechlab as ml
    >>> cam = ml.TranslatingRollerCam(ml.CamProgramme(10.0, np.pi / 2, np.pi / 2), 40.0, 10.0)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     doc = ml.write_cam_dxf(cam, os.path.join(folder, "cam.dxf"), n=50)
    >>> [entity.dxf.layer for entity in doc.modelspace()]
    ['PROFILE', 'PITCH', 'BASE']
    """
    import ezdxf

    prof = cam.profile(n)
    doc = ezdxf.new("R2010", units=4)
    for name, color in (("PROFILE", 1), ("PITCH", 5), ("BASE", 3)):
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    # the last sample repeats the first (θ = 2π): the polylines are closed instead
    msp.add_lwpolyline(prof.surface[:-1].tolist(), close=True, dxfattribs={"layer": "PROFILE"})
    msp.add_lwpolyline(prof.pitch[:-1].tolist(), close=True, dxfattribs={"layer": "PITCH"})
    msp.add_circle((0.0, 0.0), cam.base_radius, dxfattribs={"layer": "BASE"})
    doc.saveas(str(path))
    return doc
