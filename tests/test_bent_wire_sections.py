"""The bending stiffness from the cross-section (:mod:`linecontact.bent_wire.sections`).

Each shape against a computation written here that does not share the module's formula:

- **Green's theorem over the boundary**: the rounded polygon's outline drawn as its arcs
  and sides (the arcs as fine chords, Richardson-extrapolated in the chord count), its
  moments by the shoelace sums, about axes turned by any angle (the isotropy);
- **a grid quadrature** of the set of points within ``r_c`` of the sharp polygon (the
  Minkowski sum by its definition, no boundary drawn);
- closed forms of the sharp polygons (triangle, square, hexagon) and the tube;
- the limits: ``r_c -> 0`` the sharp polygon, ``r_c = R`` the disc, many sides the circle.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from linecontact.bent_wire import bending_stiffness, second_moment_of_area
from linecontact.errors import ParameterError
from linecontact.geometry import ROUND, Polygon


def _outline(radius: float, sides: int, corner: float, chords: int, turn: float = 0.0):
    """The rounded polygon's boundary, counter-clockwise: each corner's arc as ``chords``."""
    p = radius - corner
    pts = []
    for k in range(sides):
        phi = 2 * math.pi * k / sides + turn
        vx, vy = p * math.cos(phi), p * math.sin(phi)
        if corner == 0.0:
            pts.append([[vx, vy]])
            continue
        a = np.linspace(phi - math.pi / sides, phi + math.pi / sides, chords + 1)
        pts.append(np.column_stack([vx + corner * np.cos(a), vy + corner * np.sin(a)]))
    return np.concatenate(pts)


def _shoelace(xy: np.ndarray) -> tuple[float, float, float, float]:
    """Area, Ixx, Iyy, Ixy of a polygon about the origin, by Green's theorem (exact)."""
    x, y = xy[:, 0], xy[:, 1]
    x1, y1 = np.roll(x, -1), np.roll(y, -1)
    c = x * y1 - x1 * y
    area = c.sum() / 2
    ixx = (c * (y * y + y * y1 + y1 * y1)).sum() / 12
    iyy = (c * (x * x + x * x1 + x1 * x1)).sum() / 12
    ixy = (c * (x * y1 + 2 * x * y + 2 * x1 * y1 + x1 * y)).sum() / 24
    return area, ixx, iyy, ixy


def _green(radius, sides, corner, turn=0.0):
    """Ixx, Iyy, Ixy by the shoelace sums, Richardson over 400 and 800 chords per arc."""
    m1 = np.array(_shoelace(_outline(radius, sides, corner, 400, turn))[1:])
    m2 = np.array(_shoelace(_outline(radius, sides, corner, 800, turn))[1:])
    return (4 * m2 - m1) / 3  # the chords' error is second order in their length


def _grid(radius, sides, corner, cells=1200, turn=0.3):
    """Ixx by the midpoint rule over the points within ``corner`` of the sharp polygon.

    The polygon turned by ``turn`` so that no side lies along the grid's rows (a side on a
    row makes the rule's error first order in the cell).
    """
    h = 2 * radius / cells
    g = -radius + h * (np.arange(cells) + 0.5)
    X, Y = np.meshgrid(g, g, indexing="ij")
    p = radius - corner
    phi = 2 * math.pi * np.arange(sides) / sides + turn
    vx, vy = p * np.cos(phi), p * np.sin(phi)
    inside = np.ones(X.shape, bool)
    dist = np.full(X.shape, np.inf)
    for k in range(sides):
        ax, ay, bx, by = vx[k], vy[k], vx[(k + 1) % sides], vy[(k + 1) % sides]
        ex, ey = bx - ax, by - ay
        inside &= ex * (Y - ay) - ey * (X - ax) >= 0  # left of every side (CCW)
        t = np.clip(((X - ax) * ex + (Y - ay) * ey) / (ex * ex + ey * ey), 0, 1)
        dist = np.minimum(dist, np.hypot(X - ax - t * ex, Y - ay - t * ey))
    member = inside | (dist <= corner)
    return float((Y**2 * member).sum() * h * h)


@pytest.mark.parametrize(
    ("sides", "corner"), [(3, 0.0), (4, 0.2), (5, 0.1), (6, 0.0), (6, 0.15), (6, 0.7), (9, 0.4)]
)
def test_rounded_polygons_against_greens_theorem_about_turned_axes(sides, corner):
    radius = 1.3
    i = second_moment_of_area(radius, Polygon(sides, corner))
    for turn in (0.0, 0.1234, math.pi / (2 * sides), 1.0):
        ixx, iyy, ixy = _green(radius, sides, corner, turn)
        assert ixx == pytest.approx(i, rel=1e-9), f"sides={sides} r_c={corner} turn={turn}"
        assert iyy == pytest.approx(i, rel=1e-9), f"sides={sides} r_c={corner} turn={turn}"
        assert abs(ixy) < 1e-9 * i


@pytest.mark.parametrize(("sides", "corner"), [(5, 0.25), (6, 0.1), (6, 0.0), (3, 0.5)])
def test_rounded_polygons_against_a_grid_quadrature_of_the_minkowski_sum(sides, corner):
    i = second_moment_of_area(1.0, Polygon(sides, corner))
    assert _grid(1.0, sides, corner) == pytest.approx(i, rel=3e-4)


def test_sharp_polygons_closed_forms_and_the_tube():
    R = 2.0
    tri = math.sqrt(3) * (math.sqrt(3) * R) ** 4 / 96  # side sqrt(3) R
    assert second_moment_of_area(R, Polygon(3)) == pytest.approx(tri, rel=1e-14)
    assert second_moment_of_area(R, Polygon(4)) == pytest.approx((math.sqrt(2) * R) ** 4 / 12)
    hexagon = 5 * math.sqrt(3) * R**4 / 16  # side R
    assert second_moment_of_area(R, Polygon(6)) == pytest.approx(hexagon, rel=1e-14)
    assert second_moment_of_area(R) == pytest.approx(math.pi * R**4 / 4, rel=1e-15)
    tube = second_moment_of_area(R, ROUND, inner_radius=1.5)
    assert tube == pytest.approx(math.pi * (R**4 - 1.5**4) / 4, rel=1e-15)
    # the tube by the shoelace sums: the outer circle minus the inner (fine polygons)
    a = np.linspace(0, 2 * math.pi, 200001)[:-1]
    outer = _shoelace(np.column_stack([R * np.cos(a), R * np.sin(a)]))[1]
    inner = _shoelace(np.column_stack([1.5 * np.cos(a), 1.5 * np.sin(a)]))[1]
    assert tube == pytest.approx(outer - inner, rel=1e-9)


def test_limits_sharp_corner_round_corner_many_sides():
    R = 1.0
    for n in (3, 5, 6):
        sharp = second_moment_of_area(R, Polygon(n, 0.0))
        near = second_moment_of_area(R, Polygon(n, 1e-7))
        assert near == pytest.approx(sharp, rel=1e-5)
        assert near > sharp  # rounding adds area outside the smaller polygon's inradius
        assert second_moment_of_area(R, Polygon(n, R)) == pytest.approx(math.pi / 4, rel=1e-14)
        # the rounded polygon lies between its inscribed and circumscribed discs
        mid = second_moment_of_area(R, Polygon(n, 0.3))
        inradius = (R - 0.3) * math.cos(math.pi / n) + 0.3
        assert math.pi * inradius**4 / 4 < mid < math.pi * R**4 / 4
    # many sides: the circle, the gap second order in 1/n
    gaps = [math.pi / 4 - second_moment_of_area(R, Polygon(n)) for n in (100, 200, 400)]
    assert 0 < gaps[2] < gaps[1] < gaps[0] < 2e-3
    assert gaps[0] / gaps[1] == pytest.approx(4, rel=1e-3)


def test_vectorised_and_the_stiffness_is_the_modulus_times_the_moment():
    r = np.array([[10e-9], [50e-9]])
    e = np.array([70e9, 140e9, 200e9])
    ei = bending_stiffness(e, r, Polygon(6, 2e-9))
    assert ei.shape == (2, 3)
    for i in range(2):
        for j in range(3):
            one = e[j] * second_moment_of_area(float(r[i, 0]), Polygon(6, 2e-9))
            assert ei[i, j] == pytest.approx(one, rel=1e-14)
    assert isinstance(bending_stiffness(140e9, 50e-9), float)
    tubes = second_moment_of_area([2.0, 3.0], inner_radius=[1.0, 0.0])
    assert tubes == pytest.approx([math.pi * 15 / 4, math.pi * 81 / 4])
    # D = 100 nm ZnO (the wire): 140e9 * pi (50e-9)^4 / 4
    assert bending_stiffness(140e9, 50e-9) == pytest.approx(6.8722339e-19, rel=1e-7)


@pytest.mark.parametrize(
    ("call", "name", "match"),
    [
        (lambda: second_moment_of_area(-1.0), "radius", r"radius must be in \(0, inf\)"),
        (lambda: second_moment_of_area(0.0), "radius", r"radius must be in \(0, inf\)"),
        (lambda: second_moment_of_area(math.nan), "radius", "radius must be a finite"),
        (
            lambda: second_moment_of_area(1.0, inner_radius=1.0),
            "inner_radius",
            r"inner_radius must be in \[0, radius\)",
        ),
        (
            lambda: second_moment_of_area(1.0, inner_radius=-0.1),
            "inner_radius",
            r"inner_radius must be in \[0, inf\)",
        ),
        (
            lambda: second_moment_of_area(1.0, Polygon(6), inner_radius=0.5),
            "inner_radius",
            "a polygon takes none",
        ),
        (
            lambda: second_moment_of_area([1.0, 0.1], Polygon(6, 0.5)),
            "corner_radius",
            "corner_radius must be at most the circumradius",
        ),
        (lambda: second_moment_of_area(1.0, "hexagon"), "cross_section", "cross_section must"),
        (lambda: bending_stiffness(-1.0, 1.0), "modulus", r"modulus must be in \(0, inf\)"),
        (lambda: bending_stiffness(1.0, "a"), "radius", "radius must be a real number"),
    ],
)
def test_bad_input_is_refused_naming_it(call, name, match):
    with pytest.raises(ParameterError, match=match) as err:
        call()
    assert err.value.parameter == name


def test_the_stiffness_uncertainty_from_the_radius_and_the_modulus():
    """sd(EI): 4 EI sd_R/R (EI ~ R^4) and EI sd_E/E, in quadrature; a polygon whose corners
    round it whole (corner radius = circumradius) has the disc's, and takes a difference."""
    from linecontact.bent_wire import bending_stiffness_sd
    from linecontact.geometry import Polygon

    ei = bending_stiffness(140e9, 50e-9)
    r = bending_stiffness_sd(140e9, 50e-9, radius_sd=1e-9)
    assert r == pytest.approx(4 * ei * 1e-9 / 50e-9, rel=1e-5)
    e = bending_stiffness_sd(140e9, 50e-9, modulus_sd=14e9)
    assert e == pytest.approx(0.1 * ei, rel=1e-12)
    both = bending_stiffness_sd(140e9, 50e-9, modulus_sd=14e9, radius_sd=1e-9)
    assert both == pytest.approx(np.hypot(r, e), rel=1e-12)
    disc = bending_stiffness_sd(140e9, 50e-9, Polygon(6, 50e-9), radius_sd=1e-9)
    assert np.isfinite(disc) and disc > 0
    assert bending_stiffness_sd(140e9, 50e-9) == 0.0
