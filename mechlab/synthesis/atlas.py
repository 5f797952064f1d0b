"""An atlas of crank-rocker coupler curves you can search for dwells: arcs (a rocker dwells) and straight runs
(a slider dwells).

The grid follows Hrones and Nelson (1951): the crank is 1; the coupler, rocker and frame take the lengths
1, 1.5, …, 4.5, kept where the four-bar is a crank-rocker with room to spare (Grashof, s + l < p + q
strictly: 175 linkages); the coupler point (u, v) lies on a grid of step 0.25 in the coupler's frame
(u from −1.5 to 4.5 along A→B from A, v from −3 to 3 to its left: 625 points), 109,375 designs in all. Only
the assembly with B left of A→E is swept: the other one is the mirror image of the point (u, −v).

Each curve is screened vectorised (running sums, Kåsa's circle and a total-least-squares line per window,
then Lawson's reweighting on the best windows): see :func:`screen` for the method and what is stored.

Storage: the atlas ships as ``mechlab/data/atlas.npz`` (``np.savez_compressed``: ripples float32, starts
uint16, sizes and travels float16, i.e. to 0.05 %), 5.2 MB, read in 0.06–0.2 s. Building it costs about 110
CPU-seconds (about 1,000 designs per CPU-second at every grid size, Lawson's steps included), so about a
minute on the course's two cores when they are free and up to 7 minutes when the machine is shared (the
shipped file took 419 s, built beside seven other jobs): well above what ``make test`` or a student's first
query should wait, against 5.2 MB in the package. Hence shipped, not built on first use. :func:`build_atlas`
rebuilds it (``build_atlas().save(DATA)``), and a test checks the file against a fresh build of a slice of
the grid, so a stale file fails.
"""

from __future__ import annotations

import json
import os
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path
from typing import Annotated, Protocol, runtime_checkable

import numpy as np

from ..errors import DimensionError
from ..validate import Spec, angle, choice, count, length, mechanism, number, validated
from .coupler_dwell import ArcFit, RunFit, arc_dwell_sixbar, coupler_fourbar, fit_arc, fit_run, run_dwell_sixbar

DATA = Path(__file__).resolve().parent.parent / "data" / "atlas.npz"


@runtime_checkable
class _Cluster(Protocol):
    """What the Dask route needs of a client: ``map`` the chunks, ``gather`` the results."""

    def map(self, func, *iterables, **kwargs): ...

    def gather(self, futures): ...


LENGTHS = tuple(np.arange(1.0, 4.51, 0.5).tolist())  # coupler, rocker and frame (crank 1): Hrones and Nelson
U = tuple(np.round(np.arange(-1.5, 4.51, 0.25), 2).tolist())  # coupler point along A→B from A
V = tuple(np.round(np.arange(-3.0, 3.01, 0.25), 2).tolist())  # and to the left of A→B
ARC_WIDTHS = tuple(np.radians([60.0, 90.0, 120.0, 150.0]).tolist())  # crank intervals of a rocker's dwell
RUN_WIDTHS = tuple(np.radians([60.0, 90.0, 120.0]).tolist())  # and of a slider's
SAMPLES = 360  # crank angles per turn
MAX_RADIUS = 10.0  # the largest arc radius kept (crank lengths)
CANDIDATES = 4  # windows per width measured exactly, those with the least algebraic residual
LAWSON = 12  # reweighting steps towards each candidate window's minimax circle
CHUNK = 256  # designs computed at once: their work arrays (0.7 MB each) stay near the cache, 10–20 % faster than 2048
VERSION = 1


def crank_rockers(lengths) -> np.ndarray:
    """The strict crank-rockers with crank 1 and the coupler, rocker and frame taken from ``lengths``.

    Parameters
    ----------
    lengths : sequence of float
        The lengths swept for each of coupler, rocker and frame.

    Returns
    -------
    numpy.ndarray
        (crank, coupler, rocker, frame) rows, the crank the shortest link and s + l < p + q strictly, in the
        order of :func:`numpy.meshgrid` (coupler slowest).

    Examples
    --------
    >>> from mechlab.synthesis.atlas import crank_rockers
    >>> crank_rockers((2.0, 3.0)).tolist()
    [[1.0, 2.0, 2.0, 2.0], [1.0, 2.0, 3.0, 3.0], [1.0, 3.0, 2.0, 3.0], [1.0, 3.0, 3.0, 2.0], [1.0, 3.0, 3.0, 3.0]]
    """
    b, c, d = (g.ravel() for g in np.meshgrid(lengths, lengths, lengths, indexing="ij"))
    links = np.stack([b, c, d], axis=1)
    longest = links.max(axis=1)
    keep = 1.0 + longest < links.sum(axis=1) - longest - 1e-9  # Grashof with the crank shortest, strictly
    keep &= links.min(axis=1) > 1.0 + 1e-9
    return np.column_stack([np.ones(keep.sum()), links[keep]])


def _design_rows(settings: dict, index: np.ndarray) -> np.ndarray:
    """(crank, coupler, rocker, frame, u, v) of the designs ``index`` of the grid (linkage-major)."""
    linkages = crank_rockers(settings["lengths"])
    uu, vv = np.meshgrid(settings["u"], settings["v"], indexing="ij")
    points = np.column_stack([uu.ravel(), vv.ravel()])
    k, p = np.divmod(index, len(points))
    return np.column_stack([linkages[k], points[p]])


def _turn(samples: int) -> np.ndarray:
    """``samples`` crank angles spaced evenly over a turn from 0."""
    return np.arange(samples) * (2 * np.pi / samples)


def _curves(rows: np.ndarray, phi: np.ndarray):
    """Joint B and coupler point P of each design at the crank angles ``phi``: four (m, len(phi)) arrays."""
    a, b, c, d, u, v = (rows[:, i:i + 1] for i in range(6))
    ax, ay = a * np.cos(phi), a * np.sin(phi)
    ex, ey = d - ax, -ay  # A → E
    ae2 = ex * ex + ey * ey
    ae = np.sqrt(ae2)
    along = (b * b - c * c + ae2) / (2 * ae)
    h = np.sqrt(b * b - along * along)  # > 0: a strict crank-rocker never stretches nor folds
    bx = ax + (along * ex - h * ey) / ae  # B on the left of A → E (assembly +1)
    by = ay + (along * ey + h * ex) / ae
    cx, cy = (bx - ax) / b, (by - ay) / b  # the coupler's axis, unit
    return bx, by, ax + u * cx - v * cy, ay + u * cy + v * cx


def _transmission(rows: np.ndarray) -> np.ndarray:
    """Least transmission angle (rad) of each four-bar: at φ = 0 or π, where |AE| is least or largest."""
    a, b, c, d = rows[:, 0], rows[:, 1], rows[:, 2], rows[:, 3]
    mu = [np.arccos(np.clip((b * b + c * c - s * s) / (2 * b * c), -1, 1)) for s in (d - a, d + a)]
    return np.minimum(*(np.minimum(m, np.pi - m) for m in mu))


class _Running:
    """Running sums of the coordinates' powers along each (periodically extended) curve, once per chunk:
    the sum over any window of consecutive samples is then one difference, whatever its width."""

    TERMS = ("x", "y", "xx", "xy", "yy", "zx", "zy", "zz")

    def __init__(self, x: np.ndarray, y: np.ndarray, widest: int):
        self.n = x.shape[1]
        self.xe = np.concatenate([x, x[:, :widest]], axis=1)
        self.ye = np.concatenate([y, y[:, :widest]], axis=1)
        xe, ye = self.xe, self.ye
        z = xe * xe + ye * ye
        terms = (xe, ye, xe * xe, xe * ye, ye * ye, z * xe, z * ye, z * z)
        zero = np.zeros((x.shape[0], 1))
        self.cs = {k: np.concatenate([zero, np.cumsum(t, axis=1)], axis=1) for k, t in zip(self.TERMS, terms,
                                                                                          strict=True)}

    def window(self, width: int) -> dict:
        """Sums over ``width`` + 1 consecutive samples from every start: a dict of (m, n) arrays."""
        return {k: c[:, width + 1:width + 1 + self.n] - c[:, :self.n] for k, c in self.cs.items()}


def _circle_moments(s: dict, count: int):
    """Kåsa's circle for every window from its sums: centre (cx, cy), radius², algebraic residual Σ(ρ² − R²)²."""
    mx, my = s["x"] / count, s["y"] / count
    cuu, cuv, cvv = s["xx"] - count * mx * mx, s["xy"] - count * mx * my, s["yy"] - count * my * my
    # third central moments Σu³ + Σuv², Σv³ + Σu²v from Σ z·x, Σ z·y (z = x² + y²)
    zx = s["zx"] - mx * (3 * s["xx"] + s["yy"]) - 2 * my * s["xy"] + count * mx * (2 * mx * mx + 2 * my * my)
    zy = s["zy"] - my * (3 * s["yy"] + s["xx"]) - 2 * mx * s["xy"] + count * my * (2 * my * my + 2 * mx * mx)
    det = cuu * cvv - cuv * cuv
    with np.errstate(divide="ignore", invalid="ignore"):
        a = 0.5 * (cvv * zx - cuv * zy) / det
        b = 0.5 * (cuu * zy - cuv * zx) / det
    r2 = a * a + b * b + (cuu + cvv) / count
    # Σ w², w = (u − a)² + (v − b)² − R² = z' − 2au − 2bv − (cuu + cvv)/n, z' = u² + v² (central)
    zz = _central_zz(s, mx, my, count)
    tr = cuu + cvv
    resid = zz - tr * tr / count - 4 * (a * zx + b * zy) + 4 * (a * a * cuu + 2 * a * b * cuv + b * b * cvv)
    return mx + a, my + b, r2, resid


def _central_zz(s: dict, mx, my, count: int):
    """Σ ((x − x̄)² + (y − ȳ)²)² from the raw sums (the fourth moments enter through Σ z²)."""
    # z' = z − 2 x̄ x − 2 ȳ y + (x̄² + ȳ²) with z = x² + y²; expand Σ z'²
    m2 = mx * mx + my * my
    sz = s["xx"] + s["yy"]
    lin2 = 4 * (mx * mx * s["xx"] + 2 * mx * my * s["xy"] + my * my * s["yy"])  # Σ (2x̄x + 2ȳy)²
    return (s["zz"] - 4 * (mx * s["zx"] + my * s["zy"]) + lin2 + 2 * m2 * sz
            - 4 * m2 * (mx * s["x"] + my * s["y"]) + count * m2 * m2)


def _gather(xe: np.ndarray, starts: np.ndarray, width: int) -> np.ndarray:
    """The window's samples: (m, k, width + 1) from the periodically extended rows ``xe`` and starts (m, k)."""
    idx = starts[:, :, None] + np.arange(width + 1)
    return np.take_along_axis(xe[:, None, :], idx, axis=2)


def _pick(a: np.ndarray, best: np.ndarray) -> np.ndarray:
    """Each row's entry at column ``best`` (m, 1)."""
    return np.take_along_axis(a, best, 1)[:, 0]


def _lawson(px: np.ndarray, py: np.ndarray, cx: np.ndarray, cy: np.ndarray, iterations: int = LAWSON):
    """Centres nearer the minimax circle's: Lawson's reweighted least squares on the algebraic residual ρ² − R²
    (≈ 2R(ρ − R) on a near-circle), from Kåsa's centre ``cx``, ``cy``; each window keeps the better of the two.

    Each step fits the circle to the window's points with weights that grow where the last fit's residual was
    large (w ← w·|r|), which drives the largest residual down towards the minimax one (Lawson, 1961).
    """
    def spread(ox, oy):
        rho = np.hypot(px - ox, py - oy)
        return (rho.max(axis=2) - rho.min(axis=2))[..., None]

    u, v = px - px.mean(axis=2, keepdims=True), py - py.mean(axis=2, keepdims=True)
    z = u * u + v * v
    w = np.full(px.shape, 1.0 / px.shape[2])
    a = b = np.zeros(cx.shape)
    for _ in range(iterations):
        sw = w.sum(axis=2, keepdims=True)
        mu, mv, mz = ((w * t).sum(axis=2, keepdims=True) / sw for t in (u, v, z))
        du, dv, dz = u - mu, v - mv, z - mz
        suu, suv, svv = ((w * p * q).sum(axis=2, keepdims=True) for p, q in ((du, du), (du, dv), (dv, dv)))
        szu, szv = (w * dz * du).sum(axis=2, keepdims=True), (w * dz * dv).sum(axis=2, keepdims=True)
        det = suu * svv - suv * suv
        with np.errstate(invalid="ignore", divide="ignore"):
            a = 0.5 * (svv * szu - suv * szv) / det
            b = 0.5 * (suu * szv - suv * szu) / det
            resid = np.abs(z - 2 * a * u - 2 * b * v - (mz - 2 * a * mu - 2 * b * mv))
            w = w * resid
            w = w / w.sum(axis=2, keepdims=True)
        w[~np.isfinite(w)] = 1.0 / px.shape[2]  # a window fitted exactly, or degenerate: start again evenly
    lx, ly = a + px.mean(axis=2, keepdims=True), b + py.mean(axis=2, keepdims=True)
    with np.errstate(invalid="ignore"):
        better = spread(lx, ly) < spread(cx, cy)
    return np.where(better, lx, cx), np.where(better, ly, cy)


def _best_arcs(sums: _Running, width: int, max_radius: float):
    """Best arc of each curve over ``width`` + 1 samples: start, relative ripple, centre (2), radius, extent and
    travel (the whole curve's spread of ρ over the radius).

    Windows are ranked by the relative algebraic residual, √(Σw²/n) / 2R² (w = ρ² − R²: 2R·(ρ − R) to first
    order); the CANDIDATES best are measured exactly and the least relative ripple kept.
    """
    count = width + 1
    s, xe, ye = sums.window(width), sums.xe, sums.ye
    cx, cy, r2, resid = _circle_moments(s, count)
    with np.errstate(invalid="ignore", divide="ignore"):
        score = np.sqrt(np.maximum(resid, 0.0) / count) / (2 * r2)
    score[~(np.isfinite(score) & (r2 > 0) & (r2 <= max_radius ** 2))] = np.inf
    starts = np.argpartition(score, CANDIDATES, axis=1)[:, :CANDIDATES]
    starts.sort(axis=1)  # a stable order: ties measured alike whatever the partition returned
    px, py = _gather(xe, starts, width), _gather(ye, starts, width)
    ccx, ccy = np.take_along_axis(cx, starts, 1)[..., None], np.take_along_axis(cy, starts, 1)[..., None]
    ccx, ccy = _lawson(px, py, ccx, ccy)
    rho = np.hypot(px - ccx, py - ccy)
    hi, lo = rho.max(axis=2), rho.min(axis=2)
    radius = 0.5 * (hi + lo)
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = 0.5 * (hi - lo) / radius
    rel[~np.isfinite(np.take_along_axis(score, starts, 1))] = np.inf
    rel[~np.isfinite(rel)] = np.inf
    best = np.argmin(rel, axis=1)[:, None]
    # the angle the arc subtends at its centre: the sum of the turns between consecutive samples
    bx, by = (np.take_along_axis(p, best[..., None], 1)[:, 0] for p in (px, py))
    ox, oy = (np.take_along_axis(c, best[..., None], 1)[:, 0] for c in (ccx, ccy))
    ux, uy = bx - ox, by - oy
    turn = np.arctan2(ux[:, :-1] * uy[:, 1:] - uy[:, :-1] * ux[:, 1:], ux[:, :-1] * ux[:, 1:] + uy[:, :-1] * uy[:, 1:])
    r = _pick(radius, best)
    # how far the whole curve strays from the circle: what swings the output outside the dwell
    rho = np.hypot(sums.xe[:, :sums.n] - ox, sums.ye[:, :sums.n] - oy)
    with np.errstate(invalid="ignore", divide="ignore"):
        travel = np.ptp(rho, axis=1) / r
    return _pick(starts, best), _pick(rel, best), ox[:, 0], oy[:, 0], r, np.abs(turn.sum(axis=1)), travel


def _best_runs(sums: _Running, width: int):
    """Best straight run of each curve: start, relative ripple, a point (2), direction, length, ripple and travel
    (the whole curve's spread of distances from the line over the run's length)."""
    count = width + 1
    s, xe, ye = sums.window(width), sums.xe, sums.ye
    mx, my = s["x"] / count, s["y"] / count
    cuu, cuv, cvv = s["xx"] - count * mx * mx, s["xy"] - count * mx * my, s["yy"] - count * my * my
    half, gap = 0.5 * (cuu + cvv), np.hypot(0.5 * (cuu - cvv), cuv)
    with np.errstate(invalid="ignore", divide="ignore"):
        score = np.sqrt(np.maximum(half - gap, 0.0) / (half + gap))
    score[~np.isfinite(score)] = np.inf
    starts = np.argpartition(score, CANDIDATES, axis=1)[:, :CANDIDATES]
    starts.sort(axis=1)
    px, py = _gather(xe, starts, width), _gather(ye, starts, width)
    theta = 0.5 * np.arctan2(2 * np.take_along_axis(cuv, starts, 1), np.take_along_axis(cuu - cvv, starts, 1))
    ox, oy = np.take_along_axis(mx, starts, 1), np.take_along_axis(my, starts, 1)
    tx, ty = np.cos(theta)[..., None], np.sin(theta)[..., None]
    dist = (py - oy[..., None]) * tx - (px - ox[..., None]) * ty
    along = (px - ox[..., None]) * tx + (py - oy[..., None]) * ty
    ripple, run = 0.5 * np.ptp(dist, axis=2), np.ptp(along, axis=2)
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = ripple / run
    rel[~np.isfinite(rel)] = np.inf
    best = np.argmin(rel, axis=1)[:, None]
    mid = _pick(0.5 * (dist.max(axis=2) + dist.min(axis=2)), best)  # the band's middle, off the fitted line
    th = _pick(theta, best)
    length = _pick(run, best)
    qx, qy = _pick(ox, best) - mid * np.sin(th), _pick(oy, best) + mid * np.cos(th)
    off = (sums.ye[:, :sums.n] - qy[:, None]) * np.cos(th)[:, None] - (sums.xe[:, :sums.n] - qx[:, None]) * \
        np.sin(th)[:, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        travel = np.ptp(off, axis=1) / length
    return _pick(starts, best), _pick(rel, best), qx, qy, th, length, _pick(ripple, best), travel


def screen(rows: np.ndarray, settings: dict, *, detail: bool = False) -> dict:
    """The atlas's columns for the designs ``rows``: what each chunk runs, locally or on Dask.

    A pure function of its arguments, row by row: a design's columns do not depend on the chunk it is in.

    Parameters
    ----------
    rows : numpy.ndarray
        (m, 6): crank, coupler, rocker, frame, u, v of each design.
    settings : dict
        An atlas's settings (:attr:`Atlas.settings`): samples per turn, arc and run widths, largest radius.
    detail : bool, optional
        Add the fitted arcs' centres (``arc_x``, ``arc_y``), radii and extents, and the runs' lines
        (``run_x``, ``run_y``, ``run_direction``, ``run_length``, ``run_band``): for the designs a query returns.

    Returns
    -------
    dict of numpy.ndarray
        The columns of :class:`Atlas`, one row a design (with ``detail``, the fits too).

    Notes
    -----
    Each coupler curve is sampled at ``samples`` crank angles (1°), vectorised over the crank angle and over a
    chunk of designs at once. For every dwell width (a crank interval: 60°, 90°, 120°, 150° for arcs; 60°, 90°,
    120° for runs) and every start angle, a circle (Kåsa's algebraic fit) and a line (total least squares) are
    fitted to the window's points from running sums of the coordinates' powers, so each of the 360 windows costs
    a few arithmetic operations whatever its width. The four windows with the least algebraic residual are then
    fitted again, nearer the minimax circle, by Lawson's reweighted least squares (12 steps, all windows at once),
    and measured exactly: the ripple is max |ρ − R| over the window's points about the fitted centre, R the
    midrange of ρ (for a run, half the band of distances from the fitted line). The stored ripple is thus an
    upper bound of the window's minimax half-width, within 1 % of it for half the arcs a query asks for and within
    10 % for nine in ten (tests/test_atlas.py); :func:`~mechlab.synthesis.coupler_dwell.coupler_arcs` gives the
    exact minimax arc of a chosen design. Arcs whose radius exceeds ``max_radius`` (10 crank lengths) are not
    kept: a nearly straight piece is a run, and a rod that long makes no compact six-bar.

    What is stored, per design: the four-bar's least transmission angle and its size (the largest side of the
    bounding box of its pivots, joints and coupler curve); per dwell width, the best arc's start (in samples),
    ripple relative to its radius, the size with its centre (where the six-bar's dyad is attached) and its
    travel (the whole curve's spread of ρ about that centre, over the radius: what swings the output outside
    the dwell), and the best run's start, ripple relative to its length and travel (the spread of the curve's
    distances from the line, over the run's length). A query reads these; the chosen designs' fits
    (centre, radius, extent, line) are recomputed from their curves by the same code.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.synthesis.atlas import load_atlas, screen
    >>> atlas = load_atlas()
    >>> out = screen(atlas.rows([1234]), atlas.settings)
    >>> bool(np.array_equal(out["arc_ripple"][0], atlas.columns["arc_ripple"][1234]))
    True
    """
    n = settings["samples"]
    bx, by, px, py = _curves(rows, _turn(n))
    # the fits run about the curve's middle: the running sums of fourth powers lose less to rounding
    ref_x, ref_y = 0.5 * (px.max(1) + px.min(1))[:, None], 0.5 * (py.max(1) + py.min(1))[:, None]
    a, d = rows[:, 0], rows[:, 3]
    lo_x = np.minimum.reduce([np.minimum(0.0, -a), bx.min(1), px.min(1)])
    hi_x = np.maximum.reduce([np.maximum(d, a), bx.max(1), px.max(1)])
    lo_y = np.minimum.reduce([-a, by.min(1), py.min(1)])
    hi_y = np.maximum.reduce([a, by.max(1), py.max(1)])
    out = {"transmission": _stored(_transmission(rows), np.float32),
           "size": _stored(np.maximum(hi_x - lo_x, hi_y - lo_y), np.float16)}
    step = 2 * np.pi / n
    arc_k = [round(w / step) for w in settings["arc_widths"]]
    run_k = [round(w / step) for w in settings["run_widths"]]
    sums = _Running(px - ref_x, py - ref_y, max(arc_k + run_k))
    # the crank pin A and the joint B trace whole circles: a dyad there would never move its output
    u, v, b = rows[:, 4], rows[:, 5], rows[:, 1]
    degenerate = (np.abs(v) < 1e-12) & ((np.abs(u) < 1e-12) | (np.abs(u - b) < 1e-12))
    arcs, runs = [], []
    for k in arc_k:
        start, rel, ox, oy, radius, extent, travel = _best_arcs(sums, k, settings["max_radius"])
        ox, oy = ox + ref_x[:, 0], oy + ref_y[:, 0]
        size = np.maximum(np.maximum(hi_x, ox) - np.minimum(lo_x, ox), np.maximum(hi_y, oy) - np.minimum(lo_y, oy))
        rel[degenerate] = np.inf
        size[~np.isfinite(rel)] = np.inf
        arcs.append((start, rel, size, ox, oy, radius, extent, travel))
    for k in run_k:
        start, rel, ox, oy, theta, run, band, travel = _best_runs(sums, k)
        runs.append((start, rel, ox + ref_x[:, 0], oy + ref_y[:, 0], theta, run, band, travel))
    out["arc_start"] = np.stack([a[0] for a in arcs], 1).astype(np.uint16)
    out["arc_ripple"] = _stored(np.stack([a[1] for a in arcs], 1), np.float32)
    out["arc_size"] = _stored(np.stack([a[2] for a in arcs], 1), np.float16)
    out["arc_travel"] = _stored(np.stack([a[7] for a in arcs], 1), np.float16)
    out["run_start"] = np.stack([r[0] for r in runs], 1).astype(np.uint16)
    out["run_ripple"] = _stored(np.stack([r[1] for r in runs], 1), np.float32)
    out["run_travel"] = _stored(np.stack([r[7] for r in runs], 1), np.float16)
    if detail:
        for i, key in enumerate(("arc_x", "arc_y", "arc_radius", "arc_extent"), start=3):
            out[key] = np.stack([a[i] for a in arcs], 1)
        for i, key in enumerate(("run_x", "run_y", "run_direction", "run_length", "run_band"), start=2):
            out[key] = np.stack([r[i] for r in runs], 1)
    return out


def _chunk(index: np.ndarray, settings: dict) -> dict:
    """Screen the designs ``index`` of the grid (what a worker runs)."""
    return screen(_design_rows(settings, index), settings)


def _settings(lengths, u, v, samples, arc_widths, run_widths, max_radius) -> dict:
    if not all(0.0 < x <= 1000.0 for x in lengths):
        raise DimensionError(f"lengths must lie in (0, 1000] (crank lengths), got {lengths}")
    if not all(abs(x) <= 1000.0 for x in (*u, *v)):
        raise DimensionError(f"u and v (the coupler point) must lie in [−1000, 1000], got u = {u}, v = {v}")
    if not len(crank_rockers(lengths)):
        raise DimensionError(f"lengths give no crank-rocker with the crank 1 (s + l < p + q), got {lengths}")
    step = 2 * np.pi / samples
    for name, widths in (("arc_widths", arc_widths), ("run_widths", run_widths)):
        if not widths or any(not 2 * step <= w < 2 * np.pi for w in widths):
            raise DimensionError(f"{name} must be crank intervals in [2·(2π/samples), 2π), got {widths}")
    return {"version": VERSION, "lengths": [float(x) for x in lengths], "u": [float(x) for x in u],
            "v": [float(x) for x in v], "samples": int(samples), "arc_widths": [float(w) for w in arc_widths],
            "run_widths": [float(w) for w in run_widths], "max_radius": float(max_radius)}


NONE = {np.dtype(np.float32): np.finfo(np.float32).max, np.dtype(np.float16): np.finfo(np.float16).max}


def _stored(values: np.ndarray, dtype) -> np.ndarray:
    """``values`` as ``dtype``, where none was found (no arc within ``max_radius``) the type's largest number:
    finite, and above any bound a query may set."""
    dtype = np.dtype(dtype)
    big = NONE[dtype]
    return np.clip(np.where(np.isfinite(values), values, big), -big, big).astype(dtype)


def _pieces(index: np.ndarray, chunk: int) -> list[np.ndarray]:
    return [index[i:i + chunk] for i in range(0, len(index), chunk)]


@validated
def build_atlas(lengths: Annotated[tuple, Spec("samples", lo=1)] = LENGTHS,
                u: Annotated[tuple, Spec("samples", lo=1)] = U,
                v: Annotated[tuple, Spec("samples", lo=1)] = V, *,
                samples: Annotated[int, count(24, 7200)] = SAMPLES,
                arc_widths: Annotated[tuple, Spec("samples", lo=1)] = ARC_WIDTHS,
                run_widths: Annotated[tuple, Spec("samples", lo=1)] = RUN_WIDTHS,
                max_radius: Annotated[float, length()] = MAX_RADIUS,
                designs: Annotated[object, Spec("samples", lo=1, optional=True)] = None,
                chunk: Annotated[int, count(1, 100_000)] = CHUNK,
                workers: Annotated[int | None, count(1, 1024, optional=True)] = None,
                client: Annotated[object, mechanism(_Cluster, optional=True,
                                                    why="a dask.distributed.Client")] = None) -> Atlas:
    """Sweep crank-rockers and coupler points and find each coupler curve's best arcs and straight runs.

    The grid's designs are numbered linkage by linkage (the crank-rockers of ``lengths``, in the order of
    :func:`numpy.meshgrid`), the coupler points (u, v) within each; ``designs`` builds only some of them.
    The designs are cut into chunks of ``chunk``, each screened by one call of the same pure function:
    in this process (one worker or one chunk), on ``workers`` processes (default: every core), or on a Dask
    cluster when ``client`` (a ``dask.distributed.Client``) is given. The three routes give identical
    columns.

    Parameters
    ----------
    lengths : sequence of float
        The coupler's, rocker's and frame's lengths swept (the crank is 1); the strict crank-rockers are kept.
    u, v : sequence of float
        The coupler point's coordinates swept: along A→B from A, and to its left (crank lengths).
    samples : int
        Crank angles per turn (24 to 7200).
    arc_widths, run_widths : sequence of float
        The crank intervals (rad) over which arcs and straight runs are fitted, each in [2·2π/samples, 2π).
    max_radius : float
        The largest arc radius kept (crank lengths).
    designs : sequence of int, optional
        Numbers of the designs to build (default: the whole grid).
    chunk : int
        Designs per chunk.
    workers : int, optional
        Processes of the local route (default: ``os.cpu_count()``); 1 screens in this process.
    client : dask.distributed.Client, optional
        Run the chunks on this Dask cluster instead.

    Returns
    -------
    Atlas
        The columns of the designs built, with the grid's settings.

    Raises
    ------
    DimensionError
        A length outside (0, 1000] or a grid with no crank-rocker, a coupler point beyond 1000, a width outside
        its range, a design number outside the grid, or a bad count.
    TypeError
        ``client`` has no ``map`` and ``gather``.

    Examples
    --------
    >>> import numpy as np
    >>> from mechlab.synthesis.atlas import build_atlas
    >>> small = build_atlas((2.0, 3.0, 3.5), u=(0.5, 1.0), v=(0.5, 1.0), workers=1)
    >>> len(small), small.columns["arc_ripple"].shape
    (84, (84, 4))
    """
    settings = _settings(lengths, u, v, samples, arc_widths, run_widths, max_radius)
    total = len(crank_rockers(settings["lengths"])) * len(settings["u"]) * len(settings["v"])
    if designs is None:
        index = np.arange(total)
    else:
        index = np.asarray(designs)
        if not np.all((index == np.round(index)) & (index >= 0) & (index < total)):
            raise DimensionError(f"designs must be numbers of the grid's designs, 0 to {total - 1}")
        index = index.astype(np.int64)
    pieces = _pieces(index, chunk)
    if client is not None:
        results = client.gather(client.map(_chunk, pieces, settings=settings, pure=False))
    elif workers == 1 or len(pieces) == 1:
        results = [_chunk(p, settings) for p in pieces]
    else:
        with ProcessPoolExecutor(max_workers=workers or os.cpu_count()) as pool:
            results = list(pool.map(_chunk, pieces, [settings] * len(pieces)))
    columns = {k: np.concatenate([r[k] for r in results]) for k in results[0]}
    return Atlas(settings, index, columns)


@dataclass(frozen=True)
class AtlasDesign:
    """One design of the atlas: a crank-rocker, its coupler point and the arc or straight run found on its curve.

    Parameters
    ----------
    index : int
        The design's number in the atlas's grid.
    crank, coupler, rocker, frame : float
        The four-bar's lengths (the crank is 1).
    point : (float, float)
        The coupler point (u, v): along A→B from A, and to its left.
    transmission : float
        The four-bar's least transmission angle over the turn (rad).
    size : float
        The largest side of the bounding box of its pivots, joints, coupler curve (and the arc's centre).
    arc : ArcFit or None
        The arc found (a rocker's dwell), or None for a straight run.
    run : RunFit or None
        The straight run found (a slider's dwell), or None for an arc.

    Examples
    --------
    >>> from mechlab.synthesis.atlas import load_atlas
    >>> best = load_atlas().query(dwell=1.5, ripple=0.01)[0]
    >>> best.arc.ripple <= 0.01 * best.arc.radius
    True
    """

    index: int
    crank: float
    coupler: float
    rocker: float
    frame: float
    point: tuple
    transmission: float
    size: float
    arc: ArcFit | None = None
    run: RunFit | None = None

    def path(self, phi) -> np.ndarray:
        """The coupler point's positions at the crank angles ``phi``, computed in closed form (as the atlas did).

        Parameters
        ----------
        phi : float or array_like
            Crank angles (rad).

        Returns
        -------
        numpy.ndarray
            Shape (len(phi), 2): P's (x, y).

        Raises
        ------
        DimensionError
            ``phi`` is not a number or a 1-D array of finite numbers.

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab.synthesis.atlas import load_atlas
        >>> design = load_atlas().query(dwell=1.5, ripple=0.01)[0]
        >>> rho = np.hypot(*(design.path(np.linspace(*design.arc.crank_interval, 50)) - design.arc.centre).T)
        >>> bool(np.all(np.abs(rho - design.arc.radius) <= 1.1 * design.arc.ripple))
        True
        """
        phi = Spec("angles", lo=1).check("phi", phi)
        row = np.array([[self.crank, self.coupler, self.rocker, self.frame, *self.point]])
        _bx, _by, px, py = _curves(row, np.atleast_1d(phi))
        return np.column_stack([px[0], py[0]])

    def linkage(self):
        """The four-bar with its coupler point "P", built by the structure builder.

        Returns
        -------
        Linkage
            :func:`~mechlab.synthesis.coupler_dwell.coupler_fourbar` of the design's lengths and point.

        Examples
        --------
        >>> from mechlab.synthesis.atlas import load_atlas
        >>> design = load_atlas().query(dwell=1.5, ripple=0.01)[0]
        >>> design.linkage().formula()
        'I(crank) → II₂(coupler, rocker)'
        """
        return coupler_fourbar(self.crank, self.coupler, self.rocker, self.frame, point=self.point)

    def sixbar(self, **kwargs):
        """The dwell six-bar: a rocker dyad at the arc's centre, or a slotted link on the run's line.

        Parameters
        ----------
        **kwargs
            Passed to :func:`~mechlab.synthesis.coupler_dwell.arc_dwell_sixbar` (``output_pivot``) or
            :func:`~mechlab.synthesis.coupler_dwell.run_dwell_sixbar` (``pivot``).

        Returns
        -------
        Linkage
            The four-bar with the dyad whose output dwells while P runs along the arc or the run.

        Examples
        --------
        >>> from mechlab.synthesis.atlas import load_atlas
        >>> six = load_atlas().query(dwell=1.5, ripple=0.01)[0].sixbar()
        >>> six.mobility()
        1
        """
        if self.arc is not None:
            return arc_dwell_sixbar(self.linkage(), "P", self.arc, **kwargs)
        return run_dwell_sixbar(self.linkage(), "P", self.run, **kwargs)


@dataclass(frozen=True, eq=False)
class Atlas:
    """Coupler curves of crank-rockers screened for arcs and straight runs: one row a design.

    Build one with :func:`build_atlas`, load the course's with :func:`load_atlas`, search it with
    :meth:`query`.

    Parameters
    ----------
    settings : dict
        The grid (lengths, u, v), the samples per turn, the arc and run widths (rad) and the largest radius.
    index : numpy.ndarray
        The designs' numbers in the grid, one a row.
    columns : dict of numpy.ndarray
        ``transmission`` and ``size`` (one a design); ``arc_start``, ``arc_ripple`` (relative to the
        radius), ``arc_size``, ``arc_travel`` (one a design and arc width); ``run_start``, ``run_ripple``
        (relative to the run's length), ``run_travel`` (one a design and run width). See the module's
        docstring.

    Examples
    --------
    >>> from mechlab.synthesis.atlas import load_atlas
    >>> atlas = load_atlas()
    >>> len(atlas) >= 100_000
    True
    """

    settings: dict
    index: np.ndarray
    columns: dict

    def __len__(self) -> int:
        return len(self.index)

    def rows(self, which) -> np.ndarray:
        """(crank, coupler, rocker, frame, u, v) of the atlas's rows ``which``.

        Parameters
        ----------
        which : int, slice or array of int
            Rows of the atlas (not design numbers).

        Returns
        -------
        numpy.ndarray
            Shape (m, 6).

        Examples
        --------
        >>> from mechlab.synthesis.atlas import load_atlas
        >>> load_atlas().rows([0]).round(2).tolist()
        [[1.0, 1.5, 1.5, 1.5, -1.5, -3.0]]
        """
        return _design_rows(self.settings, np.atleast_1d(self.index[which]))

    @validated
    def query(self, dwell: Annotated[float, angle(0.0, 2 * np.pi, open=True)],
              ripple: Annotated[float, number(0.0, 1.0)],
              transmission: Annotated[float, angle(0.0, np.pi / 2)] = 0.0,
              size: Annotated[float | None, length(optional=True)] = None, *,
              kind: Annotated[str, choice("arc", "run")] = "arc",
              travel: Annotated[float, number(0.0, 100.0)] = 0.2,
              count: Annotated[int, count(1, 1000)] = 10,
              refine: Annotated[bool, Spec("flag")] = False) -> tuple[AtlasDesign, ...]:
        """The designs whose coupler curve dwells over ``dwell`` of the crank turn within ``ripple``, best first.

        The dwell is served by the narrowest stored width at least as wide (a design that dwells over a
        wider crank interval dwells over any part of it). Ranked by relative ripple, then by transmission
        angle (largest first).

        Parameters
        ----------
        dwell : float
            The crank interval of the dwell (rad), in (0, 2π); at most the widest stored width.
        ripple : float
            The largest ripple relative to the arc's radius (``kind="arc"``) or to the run's length
            (``kind="run"``), in [0, 1]: 0.001 is 0.1 % of the radius.
        transmission : float
            The least transmission angle of the four-bar over the turn (rad), in [0, π/2].
        size : float, optional
            The largest side of the bounding box of the four-bar, its coupler curve and (an arc) the
            arc's centre, in crank lengths; None: any size.
        kind : {"arc", "run"}
            An arc (a rocker's dwell) or a straight run (a slider's dwell).
        travel : float
            The least spread of the whole coupler curve off the arc's circle (max ρ − min ρ over the turn,
            relative to the radius) or off the run's line (relative to its length), in [0, 100]: what swings
            the output outside the dwell. A point near the crank pin traces a near-circle with a tiny ripple
            and a tiny travel, no use for a dwell; the default 0.2 leaves such curves out.
        count : int
            At most this many designs (1 to 1000).
        refine : bool
            Replace each design's screened fit by the exact minimax one over the same crank interval
            (:func:`~mechlab.synthesis.coupler_dwell.fit_arc` or ``fit_run`` on the structure builder's curve,
            0.5° apart): a ripple up to a few per cent smaller, at some 50 ms a design.

        Returns
        -------
        tuple of AtlasDesign
            The designs, best first, each with its fitted arc or run; empty when none qualifies.

        Raises
        ------
        DimensionError
            A dwell outside (0, 2π) or wider than the atlas's widest width; a ripple outside [0, 1]; a
            transmission angle outside [0, π/2]; a size that is not a positive length; an unknown kind; a
            travel outside [0, 100].

        Examples
        --------
        >>> import numpy as np
        >>> from mechlab.synthesis.atlas import load_atlas
        >>> found = load_atlas().query(np.radians(120), 0.002, transmission=np.radians(40), size=8.0)
        >>> d = found[0]
        >>> bool(d.arc.ripple <= 0.002 * d.arc.radius and d.transmission >= np.radians(40) and d.size <= 8)
        True
        """
        widths = np.asarray(self.settings[f"{kind}_widths"])
        fits = np.flatnonzero(widths >= dwell - 1e-9)
        if not fits.size:
            raise DimensionError(f"dwell must be ≤ {np.degrees(widths.max()):.0f}°, the widest {kind} of the atlas, "
                                 f"got {np.degrees(dwell):.4g}°")
        j = int(fits[np.argmin(widths[fits])])
        c = self.columns
        rel = c[f"{kind}_ripple"][:, j]
        ok = (rel <= ripple) & (c["transmission"] >= transmission) & (c[f"{kind}_travel"][:, j] >= travel)
        if size is not None:
            ok &= (c["arc_size"][:, j] if kind == "arc" else c["size"]) <= size
        rows = np.flatnonzero(ok)
        rows = rows[np.lexsort((-c["transmission"][rows], rel[rows]))][:count]
        found = self._designs(rows, kind, j)
        if refine:
            fit = fit_arc if kind == "arc" else fit_run
            found = tuple(replace(d, **{kind: fit(d.linkage(), "P", getattr(d, kind).crank_interval)}) for d in found)
        return found

    def _designs(self, rows: np.ndarray, kind: str, j: int) -> tuple[AtlasDesign, ...]:
        """The designs of ``rows`` with their fits over width ``j``, recomputed from their curves."""
        if not len(rows):
            return ()
        params = self.rows(rows)
        full = screen(params, self.settings, detail=True)
        step = 2 * np.pi / self.settings["samples"]
        width = round(self.settings[f"{kind}_widths"][j] / step) * step
        found = []
        for i, row in enumerate(rows):
            start = float(full[f"{kind}_start"][i, j]) * step
            interval = (start, start + width)
            if kind == "arc":
                radius = float(full["arc_radius"][i, j])
                fit, size = ArcFit((float(full["arc_x"][i, j]), float(full["arc_y"][i, j])), radius,
                                   float(full["arc_extent"][i, j]), interval,
                                   float(full["arc_ripple"][i, j]) * radius), self.columns["arc_size"][row, j]
                arc, run = fit, None
            else:
                run = RunFit((float(full["run_x"][i, j]), float(full["run_y"][i, j])),
                             float(full["run_direction"][i, j]), float(full["run_length"][i, j]), interval,
                             float(full["run_band"][i, j]))
                arc, size = None, self.columns["size"][row]
            a, b, cc, d, u, v = (float(x) for x in params[i])
            found.append(AtlasDesign(int(self.index[row]), a, b, cc, d, (u, v),
                                     float(self.columns["transmission"][row]), float(size), arc, run))
        return tuple(found)

    @validated
    def save(self, path: Annotated[object, Spec("path")]) -> Path:
        """Write the atlas to ``path`` (``np.savez_compressed``: float32 and uint16 columns).

        Parameters
        ----------
        path : str or path-like
            The file to write (``.npz``).

        Returns
        -------
        pathlib.Path
            ``path``.

        Raises
        ------
        DimensionError
            ``path`` is not a path.

        Examples
        --------
        >>> import tempfile, pathlib
        >>> from mechlab.synthesis.atlas import build_atlas, load_atlas
        >>> small = build_atlas((2.0, 3.0, 3.5), u=(0.5,), v=(0.5,), workers=1)
        >>> with tempfile.TemporaryDirectory() as tmp:
        ...     len(load_atlas(small.save(pathlib.Path(tmp) / "small.npz")))
        21
        """
        path = Path(path)
        index = self.index
        compact = np.array_equal(index, np.arange(len(index)))  # the whole grid: the numbers go without saying
        np.savez_compressed(path, settings=np.array(json.dumps(self.settings)),
                            index=np.array([], np.int64) if compact else index, **self.columns)
        return path


@cache
def _load(path: Path, stamp: float) -> Atlas:
    try:
        with np.load(path, allow_pickle=False) as f:
            settings = json.loads(str(f["settings"]))
            columns = {k: f[k] for k in f.files if k not in ("settings", "index")}
            index = f["index"]
    except (OSError, ValueError, KeyError) as err:
        raise DimensionError(f"path {str(path)!r} holds no atlas written by Atlas.save: {err}") from None
    if not len(index):
        index = np.arange(len(columns["transmission"]))
    return Atlas(settings, index, columns)


@validated
def load_atlas(path: Annotated[object, Spec("path", optional=True)] = None) -> Atlas:
    """The course's atlas (shipped with the package), or the one saved at ``path``; read once per file.

    Parameters
    ----------
    path : str or path-like, optional
        An atlas written by :meth:`Atlas.save` (default: the shipped ``mechlab/data/atlas.npz``).

    Returns
    -------
    Atlas
        The atlas.

    Raises
    ------
    DimensionError
        ``path`` is no file, or holds no atlas.
    TypeError
        ``path`` is not a path.

    Examples
    --------
    >>> from mechlab.synthesis.atlas import load_atlas
    >>> atlas = load_atlas()
    >>> len(atlas), [round(float(w), 4) for w in atlas.settings["arc_widths"]]
    (109375, [1.0472, 1.5708, 2.0944, 2.618])
    """
    path = Path(DATA if path is None else path).resolve()
    if not path.is_file():
        raise DimensionError(f"path {str(path)!r} is no file (an atlas is written by Atlas.save)")
    return _load(path, path.stat().st_mtime)
