"""scipy's names: the same calls on scipy.interpolate (the oracle, at test time) and on
casteljau, compared at 1e-12 relative (the issue's bar; both evaluate the same
polynomials in double, a few dozen roundings apart)."""

import numpy as np
import pytest
import scipy.interpolate as si

import casteljau

REL = 1e-12


def close(a, b, rel=REL):
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape, (a.shape, b.shape)
    # Relative to the data's size: values near a zero of the spline have no relative accuracy.
    scale = max(1.0, float(np.max(np.abs(b)))) if b.size else 1.0
    np.testing.assert_allclose(a, b, rtol=rel, atol=rel * scale)


RNG = np.random.default_rng(16)
X = np.sort(RNG.random(9)) * 10
Y = np.sin(X) + RNG.random(9)
XS = np.linspace(X[0] - 1, X[-1] + 1, 101)  # extrapolated at both ends too


@pytest.mark.parametrize("bc", ["not-a-knot", "natural", "clamped", ((1, 0.5), (2, -1.0)), ("natural", "clamped")])
def test_cubic_spline(bc):
    ours, theirs = casteljau.CubicSpline(X, Y, bc_type=bc), si.CubicSpline(X, Y, bc_type=bc)
    for nu in range(4):
        close(ours(XS, nu), theirs(XS, nu))
    assert ours(2.5).shape == theirs(2.5).shape == ()
    close(ours.x, theirs.x, rel=0)
    close(ours.c, theirs.c)
    close(ours.derivative()(XS), theirs.derivative()(XS))
    close(ours.derivative(2)(XS), theirs.derivative(2)(XS))
    inside = XS[(XS >= X[0]) & (XS <= X[-1])]
    close(ours.antiderivative()(inside), theirs.antiderivative()(inside))
    close(ours.antiderivative(2)(inside), theirs.antiderivative(2)(inside))
    # Beyond the data the antiderivative's end pieces (Bernstein form of degree 4 and 5 on an
    # interval of width 0.23) are evaluated at s down to -4.3 in their own parameter:
    # rounding grows like (1 + 2|s|)^n there, about 1e4 for n = 4 (mpmath puts scipy's
    # power form, not ours, within 1e-15 of the integral over [-3, 12]).
    close(ours.antiderivative()(XS), theirs.antiderivative()(XS), rel=1e-10)
    close(ours.antiderivative(2)(XS), theirs.antiderivative(2)(XS), rel=1e-10)
    close(ours.integrate(X[1], X[-2]), theirs.integrate(X[1], X[-2]))
    close(ours.integrate(-3.0, 12.0), theirs.integrate(-3.0, 12.0), rel=1e-10)


def test_cubic_spline_roots_and_shapes():
    y = np.cos(X)
    ours, theirs = casteljau.CubicSpline(X, y), si.CubicSpline(X, y)
    close(ours.roots(extrapolate=False), theirs.roots(extrapolate=False), rel=1e-10)  # root conditioning
    close(ours.roots(), theirs.roots(), rel=1e-10)
    # Vector data (n, 2, 2) keeps scipy's shapes; periodic with extrapolate.
    Y3 = RNG.random((9, 2, 2))
    close(casteljau.CubicSpline(X, Y3)(XS.reshape(1, -1)), si.CubicSpline(X, Y3)(XS.reshape(1, -1)))
    Yp = np.sin(np.linspace(0, 2 * np.pi, 9))
    Yp[-1] = Yp[0]
    xp = np.linspace(0, 2 * np.pi, 9)
    close(casteljau.CubicSpline(xp, Yp, bc_type="periodic")(XS), si.CubicSpline(xp, Yp, bc_type="periodic")(XS))
    # extrapolate=False: NaN outside, as scipy.
    close(casteljau.CubicSpline(X, Y, extrapolate=False)(XS), si.CubicSpline(X, Y, extrapolate=False)(XS))


def test_pickled_scipy_objects_keep_scipys_shapes():
    import pickle

    for ours in (casteljau.CubicSpline(X, Y), casteljau.BSpline([0, 0, 0, 1, 2, 2, 2], [1.0, 2.0, 0.0, 1.0], 2),
                 casteljau.PchipInterpolator(X, Y)):
        again = pickle.loads(pickle.dumps(ours))
        assert type(again) is type(ours)
        np.testing.assert_array_equal(again(XS), ours(XS))
        assert again(1.5).shape == ()


def test_bsplines():
    t = np.r_[0, 0.5, 1, 2, 3.5, 4, 5, 6, 7.5]  # unclamped: the domain is [t[k], t[n]]
    c = RNG.random(5)
    ours, theirs = casteljau.BSpline(t, c, 3), si.BSpline(t, c, 3)
    xs = np.linspace(1, 6, 50)
    close(ours(xs), theirs(xs))
    close(ours(xs, 1), theirs(xs, 1))
    close(ours.integrate(2, 5), theirs.integrate(2, 5))
    c2 = RNG.random((5, 3))
    close(casteljau.BSpline(t, c2, 3)(xs), si.BSpline(t, c2, 3)(xs))
    for k in (1, 2, 3, 5):
        close(casteljau.make_interp_spline(X, Y, k=k)(XS), si.make_interp_spline(X, Y, k=k)(XS))


def test_hermite_interpolators():
    xs = np.linspace(X[0], X[-1], 77)
    close(casteljau.PchipInterpolator(X, Y)(XS), si.PchipInterpolator(X, Y)(XS))
    close(casteljau.Akima1DInterpolator(X, Y)(xs), si.Akima1DInterpolator(X, Y)(xs))
    close(casteljau.Akima1DInterpolator(X, Y)(XS), si.Akima1DInterpolator(X, Y)(XS))  # NaN outside, both
    close(casteljau.PchipInterpolator(X, Y).derivative()(xs), si.PchipInterpolator(X, Y).derivative()(xs))
    close(casteljau.PchipInterpolator(X, Y).c, si.PchipInterpolator(X, Y).c)
    # The degree-8 interpolating polynomial on 9 random nodes: its two evaluations (ours
    # through the Bezier form, scipy's barycentric formula) differ by eps times the
    # Lebesgue constant of the nodes (about 1e5 here); compared inside the nodes' hull.
    close(casteljau.BarycentricInterpolator(X, Y)(xs), si.BarycentricInterpolator(X, Y)(xs), rel=1e-9)


def test_errors_name_scipys_arguments():
    with pytest.raises(casteljau.Error, match=r"^x\[2\]: x must be strictly increasing"):
        casteljau.CubicSpline([0, 1, 1, 2], [0, 1, 2, 3])
    with pytest.raises(casteljau.Error, match=r"^y\[1\]: must be a finite number"):
        casteljau.CubicSpline([0, 1, 2], [0, np.nan, 2])
    knots = [0, 0, 0, 1, 0.5, 2, 2, 2]  # decreasing at index 4
    with pytest.raises(casteljau.Error, match=r"^t\[4\]: "):
        casteljau.BSpline(knots, [1, 2, 3, 4, 5], 2)
    with pytest.raises(casteljau.Error, match=r"^knots\[4\]: "):
        casteljau.BSpline(degree=2, knots=knots, points=[[1], [2], [3], [4], [5]])
    with pytest.raises(casteljau.Error, match=r"^x\[1\]: "):
        casteljau.CubicSpline([0, 1, 2], [0, 1, 2])(np.array([0.5, np.nan]))
    with pytest.raises(casteljau.Error, match=r"^bc_type: "):
        casteljau.CubicSpline(X, Y, bc_type="nonsense")
    with pytest.raises(ValueError):  # the same exception class scipy's callers catch
        casteljau.PchipInterpolator([0, 0, 1], [1, 2, 3])


@pytest.mark.parametrize("bc", [("not-a-knot", (1, 0.5)), ((2, -1.0), "not-a-knot"), ("natural", "not-a-knot"),
                                ("not-a-knot", "clamped")])
def test_cubic_spline_not_a_knot_at_one_end(bc):
    ours, theirs = casteljau.CubicSpline(X, Y, bc_type=bc), si.CubicSpline(X, Y, bc_type=bc)
    for nu in range(3):
        close(ours(XS, nu), theirs(XS, nu))
    # Vector data (scipy wants a value per coordinate) and two points (scipy: the chord's
    # slope at the not-a-knot end).
    Y2 = RNG.random((9, 3))
    bc2 = tuple((b[0], np.full(3, b[1])) if isinstance(b, tuple) else b for b in bc)
    close(casteljau.CubicSpline(X, Y2, bc_type=bc2)(XS), si.CubicSpline(X, Y2, bc_type=bc2)(XS))
    close(casteljau.CubicSpline(X[:2], Y[:2], bc_type=bc)(XS), si.CubicSpline(X[:2], Y[:2], bc_type=bc)(XS))


def test_make_interp_spline_degree_0_and_end_conditions():
    ours, theirs = casteljau.make_interp_spline(X, Y, k=0), si.make_interp_spline(X, Y, k=0)
    # Outside, at every data site (the right piece answers) and between them.
    for xs in (XS, X):
        close(ours(xs), theirs(xs))
    close(ours.t, theirs.t, rel=0)
    close(ours.c, theirs.c, rel=0)
    for k, bc in ((3, "natural"), (3, "clamped"), (3, ([(1, 2.0)], [(2, -0.5)])), (2, ([(1, 0.3)], None)),
                  (5, ([(1, 0.0), (2, 1.0)], [(1, -1.0), (2, 0.0)])), (4, ([(1, 0.0), (2, 0.0)], [(1, 0.0)]))):
        ours, theirs = casteljau.make_interp_spline(X, Y, k=k, bc_type=bc), si.make_interp_spline(X, Y, k=k, bc_type=bc)
        close(ours(XS), theirs(XS))
        close(ours.t, theirs.t, rel=0)
        close(ours.c, theirs.c)
    Y2 = RNG.random((9, 2))
    close(casteljau.make_interp_spline(X, Y2, k=3, bc_type="natural")(XS),
          si.make_interp_spline(X, Y2, k=3, bc_type="natural")(XS))
    # Even degrees above 2 without knots or end conditions: scipy 1.10 refuses them, so do we.
    with pytest.raises(ValueError):
        si.make_interp_spline(X, Y, k=4)
    with pytest.raises(casteljau.Error, match=r"^k: even degrees above 2"):
        casteljau.make_interp_spline(X, Y, k=4)
    with pytest.raises(casteljau.Error, match=r"^bc_type: 1 \+ 1 end derivatives given, the knots need 3"):
        casteljau.make_interp_spline(X, Y, k=4, bc_type="natural")


def test_derivatives_have_scipys_types():
    t = np.r_[0, 0, 0, 0, 1, 2.5, 3, 4, 4, 4, 4]
    c = RNG.random((7, 2))
    ours, theirs = casteljau.BSpline(t, c, 3), si.BSpline(t, c, 3)
    for nu in (1, 2, 3):
        d, e = ours.derivative(nu), theirs.derivative(nu)
        assert isinstance(d, casteljau.BSpline) and isinstance(e, si.BSpline)
        assert d.k == e.k
        close(d.t, e.t, rel=0)
        n = len(e.t) - e.k - 1  # scipy pads c with zeros to len(t); the coefficients in use
        close(d.c[:n], e.c[:n])
        xs = np.linspace(-0.5, 4.5, 41)
        close(d(xs), e(xs))
    s, u = casteljau.CubicSpline(X, Y), si.CubicSpline(X, Y)
    d, e = s.derivative(), u.derivative()
    assert isinstance(d, casteljau.PPoly) and isinstance(e, si.PPoly)  # scipy's PPoly, ours PPoly-like
    close(d.x, e.x, rel=0)
    close(d.c, e.c)
    close(d.derivative()(XS), e.derivative()(XS))


def test_more_than_four_values_per_point_name_the_data():
    # More than 4 numbers per point: scipy's classes take them (one library curve per group
    # of at most 4 columns, tested against scipy below); a bad number names its place in
    # the data, the library's own curve methods and classes refuse them, naming y.
    y = np.zeros((5, 7))
    y[2, 5] = np.nan
    for make in (casteljau.CubicSpline, casteljau.PchipInterpolator):
        with pytest.raises(casteljau.Error, match=r"^y\[2\]\[5\]: must be a finite number"):
            make(np.arange(5.0), y)
    with pytest.raises(casteljau.Error, match=r"^c\[2\]\[5\]: must be a finite number"):
        casteljau.BSpline(np.r_[0, 0, 0, 1, 2, 3, 3, 3.0], y, 2)
    s = casteljau.CubicSpline(X, RNG.random((9, 5)))
    with pytest.raises(casteljau.Error, match=r"^y: values of shape \(5,\) \(5 numbers per point\)"):
        s.length()
    with pytest.raises(casteljau.Error, match=r"^c: values of shape \(2, 3\)"):
        casteljau.BSpline(np.r_[0, 0, 1, 2, 2], RNG.random((3, 2, 3)), 1).to_json()
    with pytest.raises(casteljau.Error, match=r"^points\[0\]: point has 5 coordinates"):
        casteljau.Bezier(np.zeros((3, 5)))  # the geometric classes: dimension 1..4


def test_bspline_antiderivative_is_a_bspline():
    for t in (np.r_[0, 0.5, 1, 2, 3.5, 4, 5, 6, 7.5], np.r_[0, 0, 0, 0, 1, 2.5, 3, 4, 4, 4, 4]):
        for c in (RNG.random(len(t) - 4), RNG.random((len(t) - 4, 2))):
            ours, theirs = casteljau.BSpline(t, c, 3), si.BSpline(t, c, 3)
            for nu in (1, 2):
                a, b = ours.antiderivative(nu), theirs.antiderivative(nu)
                assert isinstance(a, casteljau.BSpline) and isinstance(b, si.BSpline)
                assert a.k == b.k == 3 + nu
                close(a.t, b.t, rel=0)
                n = len(b.t) - b.k - 1  # scipy pads c with zeros to len(t)
                close(a.c[:n], b.c[:n])
                # Inside the base interval; beyond it the end pieces continued (the
                # rounding of their Bernstein form grows with the distance, as above).
                lo, hi = t[3], t[-4]
                inside, outside = np.linspace(lo, hi, 41), np.r_[np.linspace(-0.5, lo, 9), np.linspace(hi, 8.0, 9)]
                close(a(inside), b(inside))
                close(a(inside, 1), b(inside, 1))
                close(a(outside), b(outside), rel=1e-10)
            close(ours.antiderivative().derivative()(inside), theirs(inside))
    # make_interp_spline's k = 0 (knots ending with x[-1] twice): the same function on the
    # base interval (from x[-1] on, scipy's zero-length last span gives 0: left out).
    a, b = (m.make_interp_spline(X, Y, k=0).antiderivative() for m in (casteljau, si))
    inside = np.linspace(X[0], X[-1], 41)[:-1]
    close(a(inside), b(inside))
    # extrapolate='periodic' gives a non-periodic antiderivative, extrapolate False, as scipy.
    x = np.linspace(0, 2 * np.pi, 9)
    y = np.sin(x)
    y[-1] = y[0]
    a, b = (m.make_interp_spline(x, y, k=3, bc_type="periodic").antiderivative() for m in (casteljau, si))
    assert a.extrapolate is False and b.extrapolate is False
    close(a(XS), b(XS))  # NaN outside, both


@pytest.mark.parametrize("k", [1, 2, 3, 4, 5])
def test_make_interp_spline_periodic(k):
    # Intervals 0.5 to 1.5 wide: the derivative of order nu scales the coefficients'
    # rounding (scipy solves by Woodbury's formula, we by LU) by 1 / h^nu.
    x = np.cumsum(0.5 + RNG.random(8))
    y = np.cos(x) + RNG.random(8)
    y[-1] = y[0]
    ours, theirs = casteljau.make_interp_spline(x, y, k=k, bc_type="periodic"), si.make_interp_spline(x, y, k=k, bc_type="periodic")
    assert ours.k == theirs.k and ours.extrapolate == theirs.extrapolate
    close(ours.t, theirs.t)
    close(ours.c, theirs.c)
    xs = np.linspace(x[0] - 12, x[-1] + 15, 151)  # periodic continuation, several periods
    for nu in range(k):
        close(ours(xs, nu), theirs(xs, nu))
    close(ours.integrate(x[0] - 12.5, x[-1] + 14.0), theirs.integrate(x[0] - 12.5, x[-1] + 14.0))
    close(ours.integrate(3.0, -20.0), theirs.integrate(3.0, -20.0))
    # Vector data, and fewer points than the degree needs (scipy: its full-matrix path).
    Y2 = RNG.random((8, 2))
    Y2[-1] = Y2[0]
    close(casteljau.make_interp_spline(x, Y2, k=k, bc_type="periodic")(xs),
          si.make_interp_spline(x, Y2, k=k, bc_type="periodic")(xs))
    if k >= 3:
        close(casteljau.make_interp_spline(x[:3], Y2[[0, 1, 0]], k=k, bc_type="periodic")(xs),
              si.make_interp_spline(x[:3], Y2[[0, 1, 0]], k=k, bc_type="periodic")(xs))


def test_periodic_errors_and_integrals():
    with pytest.raises(ValueError):
        si.make_interp_spline(X, Y, k=3, bc_type="periodic")
    with pytest.raises(casteljau.Error, match=r"^y: the first and last values must be equal"):
        casteljau.make_interp_spline(X, Y, k=3, bc_type="periodic")
    with pytest.raises(casteljau.Error, match=r"^x\[3\]: x must be strictly increasing"):
        casteljau.make_interp_spline([0, 1, 2, 2, 3], [0, 1, 2, 1, 0], k=3, bc_type="periodic")
    # CubicSpline's periodic extrapolation integrates over whole periods and the rest.
    xp = np.linspace(0, 2 * np.pi, 9)
    yp = np.sin(xp) + 0.3
    yp[-1] = yp[0]
    ours, theirs = casteljau.CubicSpline(xp, yp, bc_type="periodic"), si.CubicSpline(xp, yp, bc_type="periodic")
    for a, b in ((-3.0, 12.0), (1.0, 2.0), (5.0, 7.0), (20.0, -9.5)):
        close(ours.integrate(a, b), theirs.integrate(a, b))


def test_make_interp_spline_one_sided_conditions_are_refused_as_scipy():
    # scipy 1.10's knots with end derivatives need both ends' conditions; 'not-a-knot' is
    # not an end condition of make_interp_spline (CubicSpline has it, tested above).
    for bc in ((None, [(1, 0.0)]), ("not-a-knot", [(1, 0.0)])):
        with pytest.raises(ValueError):
            si.make_interp_spline(X, Y, k=3, bc_type=bc)
        with pytest.raises(casteljau.Error, match=r"^bc_type: "):
            casteljau.make_interp_spline(X, Y, k=3, bc_type=bc)


@pytest.mark.parametrize("k", [2, 4, 6])
def test_make_interp_spline_even_degrees_with_knots(k):
    # Even degrees with the caller's knots (k + 1 copies of each end, the interior from the
    # data sites), as scipy: coefficients and values.
    x = np.sort(RNG.random(12)) * 10
    y = np.sin(x) + RNG.random(12)
    h = (k + 1) // 2
    t = np.r_[(x[0],) * (k + 1), x[h : h + len(x) - k - 1], (x[-1],) * (k + 1)]
    ours, theirs = casteljau.make_interp_spline(x, y, k=k, t=t), si.make_interp_spline(x, y, k=k, t=t)
    close(ours.c, theirs.c[: len(ours.c)])
    close(ours(XS), theirs(XS))


def test_make_interp_spline_refuses_what_scipy_refuses():
    # scipy 1.10: ValueError "Expect x to be a 1D strictly increasing sequence." for
    # unsorted x and "Expect x to not have duplicates" for a repeated one; we accepted
    # the unsorted x silently (a wrong spline) and reported a NaN in y as c[0].
    for x in ([0, 2, 1, 3], [0, 1, 1, 3]):
        with pytest.raises(ValueError):
            si.make_interp_spline(x, [0, 1, 2, 3])
        with pytest.raises(casteljau.Error, match=r"^x\[2\]: x must be strictly increasing"):
            casteljau.make_interp_spline(x, [0, 1, 2, 3])
    with pytest.raises(ValueError):  # scipy: "Array must not contain infs or nans."
        si.make_interp_spline([0, 1, 2, 3], [0, 1, np.nan, 3])
    with pytest.raises(casteljau.Error, match=r"^y\[2\]: must be a finite number"):
        casteljau.make_interp_spline([0, 1, 2, 3], [0, 1, np.nan, 3])
    with pytest.raises(casteljau.Error, match=r"^x\[1\]: must be a finite number"):
        casteljau.make_interp_spline([0, np.nan, 2, 3], [0, 1, 2, 3])


def test_bspline_with_too_few_coefficients_names_c():
    with pytest.raises(ValueError):  # scipy: "Knots, coefficients and degree are inconsistent."
        si.BSpline([0, 0, 0, 1, 1, 1], [1.0], 2)
    with pytest.raises(casteljau.Error, match=r"^c: needs at least k \+ 1 = 3 coefficients, got 1$"):
        casteljau.BSpline([0, 0, 0, 1, 1, 1], [1.0], 2)


@pytest.mark.parametrize("name", ["CubicSpline", "PchipInterpolator", "Akima1DInterpolator", "BSpline"])
def test_integrate_without_extrapolation_as_scipy(name):
    # scipy 1.10's PPoly (CubicSpline, Pchip, Akima): NaN once a or b leaves [x[0], x[-1]]
    # with extrapolate=False; its BSpline clips [a, b] to the base interval. We clipped
    # for all four.
    x, y = [0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 4.0, 2.0]
    if name == "BSpline":
        theirs, ours = (mod.make_interp_spline(x, y, k=3) for mod in (si, casteljau))
    else:
        theirs, ours = getattr(si, name)(x, y), getattr(casteljau, name)(x, y)
    ranges = [(0, 3), (-1, 2), (1, 4), (-1, 4), (3, 0), (4, 1), (0.5, 2.5), (3, 3), (-2, -1)]
    for a, b in ranges:
        want = theirs.integrate(a, b, extrapolate=False)
        got = ours.integrate(a, b, extrapolate=False)
        assert np.shape(got) == np.shape(want)
        if name != "BSpline" and not (0 <= a <= 3 and 0 <= b <= 3):
            assert np.isnan(want) and np.isnan(got)
        else:
            close(got, want, rel=1e-12)


def test_roots_of_lower_degree_data_have_no_rounding_roots():
    # Linear data through a cubic spline leaves rounding-size s^3 and s^2 coefficients on
    # the end pieces; kept, they gave a root near 1 / eps: [0, 3.36e7] where scipy 1.10
    # says [0.]. On a finer grid scipy's own coefficients do the same (4.5e15 beside 1.5),
    # so there the exact roots are the oracle.
    close(casteljau.CubicSpline([0, 1, 2, 3], [0, 1, 2, 3]).roots(), si.CubicSpline([0, 1, 2, 3], [0, 1, 2, 3]).roots())
    for x in ([0.0, 1.0, 2.0, 3.0], [0.0, 0.5, 2.0, 3.0, 7.0], np.linspace(-3, 5, 9)):
        x = np.asarray(x)
        for y, exact in ((x, [0.0]), (x - 1.5, [1.5]), (2.5 - x, [2.5]), (1e-3 * (x + 0.25), [-0.25]),
                         ((x - 1) * (x - 2), [1.0, 2.0])):
            for extrapolate in (True, False):
                want = [r for r in exact if extrapolate or x[0] <= r <= x[-1]]
                close(casteljau.CubicSpline(x, y).roots(extrapolate=extrapolate), want, rel=1e-9)


def test_solve_as_scipys_ppoly_solve():
    # scipy's PPoly.solve(y, discontinuity=True, extrapolate=None): the x where the 1-D
    # function equals y (with extrapolate, on the end pieces continued too). Made scipy's
    # way, CubicSpline(x, y).solve(y) used to reach the registry's solve(value, axis) and
    # fail for want of an axis.
    x = np.linspace(0.0, 4.0, 9)
    y = np.cos(x)
    for name in ("CubicSpline", "PchipInterpolator", "Akima1DInterpolator"):
        ours, theirs = getattr(casteljau, name)(x, y), getattr(si, name)(x, y)
        for level in (0.5, -0.25, 0.0):
            for extrapolate in (None, True, False):
                # scipy lists an end piece's extrapolated roots unsorted; ours ascend.
                want = np.sort(theirs.solve(level, extrapolate=extrapolate))
                close(ours.solve(level, extrapolate=extrapolate), want, rel=1e-10)
            close(ours.derivative().solve(level), np.sort(theirs.derivative().solve(level)), rel=1e-10)
    sq = np.arange(5.0)
    close(casteljau.CubicSpline(sq, sq**2).solve(2.0), [-np.sqrt(2), np.sqrt(2)])  # scipy: [-1.414, 1.414]
    # The library's own form keeps the registry's solve(value, axis).
    c = casteljau.CubicSpline(params=sq, points=np.c_[sq, sq**2])
    close(c.solve(value=2.0, axis=0).t, [2.0], rel=1e-12)  # x(t) = t: linear data


def test_roots_of_an_identically_zero_piece_as_scipy():
    # scipy's PPoly.roots: "If sections are identically zero, root list contains the start
    # point of the interval followed by nan" (scipy 1.10: [0.99999999, 1, nan, 2] for
    # this Pchip, the first and last from the neighbouring pieces). We reported nothing.
    x, y = [0.0, 1.0, 2.0, 3.0], [2.0, 0.0, 0.0, 2.0]
    theirs = si.PchipInterpolator(x, y).roots(extrapolate=False)
    ours = casteljau.PchipInterpolator(x, y).roots(extrapolate=False)
    assert np.isnan(ours).sum() == np.isnan(theirs).sum() == 1
    i = int(np.flatnonzero(np.isnan(ours))[0])
    assert ours[i - 1] == 1.0 and theirs[int(np.flatnonzero(np.isnan(theirs))[0]) - 1] == 1.0
    assert np.all(np.abs(ours[np.isfinite(ours)] - 1.5) <= 0.5 + 1e-12)  # within [1, 2]


def test_a_root_at_the_end_is_reported_once():
    # The last piece's power form gave the root at x[-1] again as an extrapolated root
    # (s = 1 + rounding): Pchip [2, 0, 0, 2] solve(2) had 3 twice; scipy 1.10 once.
    x, y = [0.0, 1.0, 2.0, 3.0], [2.0, 0.0, 0.0, 2.0]
    close(casteljau.PchipInterpolator(x, y).solve(2.0), si.PchipInterpolator(x, y).solve(2.0), rel=1e-10)
    for ys in ([0.0, 1.0, 3.0, 2.0], [3.0, 1.0, -1.0, 0.0]):
        for cls in ("CubicSpline", "PchipInterpolator"):
            r = getattr(casteljau, cls)(x, ys).roots()
            assert len(r) == len(np.unique(np.round(r, 9))), r
            close(r, np.sort(getattr(si, cls)(x, ys).roots()), rel=1e-10)


# Session 13: extrapolation far outside the domain, scipy's axis, BarycentricInterpolator
# at any number of nodes.

FAR_X = np.sort(RNG.random(30)) * 10 + 1000  # an offset domain: the pieces' local powers matter
FAR_Y = np.cos(FAR_X) + np.linspace(0, 3, 30)
FAR_L = FAR_X[-1] - FAR_X[0]
FAR_XS = np.r_[FAR_X[0] - FAR_L * np.array([10, 3, 1, 0.1, 1e-3]), FAR_X[-1] + FAR_L * np.array([1e-3, 0.1, 1, 3, 10])]


def far_close(ours, theirs, nus=range(4), rel=1e-12):
    """ours and scipy's object agree outside the domain, pointwise relative (the values
    there grow like |x|^k: the size of the data is no scale for them)."""
    for nu in nus:
        a, b = ours(FAR_XS, nu), theirs(FAR_XS, nu)
        np.testing.assert_allclose(a, b, rtol=rel, atol=0, err_msg=f"nu={nu}")


@pytest.mark.parametrize("bc", ["natural", "clamped", ((1, 0.5), (2, -1.0)), "not-a-knot"])
def test_cubic_spline_extrapolates_as_scipy(bc):
    # scipy continues the end pieces' power forms about their left breaks; ours did the
    # Hermite form about the nearer end (1e-13 .. 1e-11 apart at 10 domain lengths).
    ours, theirs = casteljau.CubicSpline(FAR_X, FAR_Y, bc_type=bc), si.CubicSpline(FAR_X, FAR_Y, bc_type=bc)
    # not-a-knot: the library's slopes carry about 1e-14 relative more error than scipy's
    # pivoted solve (measured against the exact solve in rationals: 2e-14 and 4e-16); far
    # out that is all that remains.
    far_close(ours, theirs, rel=1e-12)
    far_close(ours.derivative(), theirs.derivative(), nus=[0, 1], rel=1e-12)
    far_close(ours.antiderivative(), theirs.antiderivative(), nus=[0, 1], rel=1e-12)


def test_hermite_interpolators_and_bsplines_extrapolate_as_scipy():
    far_close(casteljau.PchipInterpolator(FAR_X, FAR_Y), si.PchipInterpolator(FAR_X, FAR_Y))
    ours, theirs = casteljau.Akima1DInterpolator(FAR_X, FAR_Y), si.Akima1DInterpolator(FAR_X, FAR_Y)
    for nu in range(3):
        np.testing.assert_allclose(ours(FAR_XS, nu, extrapolate=True), theirs(FAR_XS, nu, extrapolate=True), rtol=1e-12)
    for k in (1, 2, 3, 5):
        t = np.r_[FAR_X[0] - 2.0, FAR_X[0] - 1.0, FAR_X[::2], FAR_X[-1] + 1.0, FAR_X[-1] + 3.0]  # unclamped ends
        c = RNG.normal(size=(len(t) - k - 1, 2))
        far_close(casteljau.BSpline(t, c, k), si.BSpline(t, c, k), nus=range(k + 1))
        far_close(casteljau.make_interp_spline(FAR_X, FAR_Y, k), si.make_interp_spline(FAR_X, FAR_Y, k),
                  nus=range(k + 1))


AXIS_CASES = [
    ("CubicSpline", lambda m, x, y, a: m.CubicSpline(x, y, axis=a)),
    ("CubicSpline natural", lambda m, x, y, a: m.CubicSpline(x, y, axis=a, bc_type="natural")),
    ("PchipInterpolator", lambda m, x, y, a: m.PchipInterpolator(x, y, axis=a)),
    ("Akima1DInterpolator", lambda m, x, y, a: m.Akima1DInterpolator(x, y, axis=a)),
    ("BarycentricInterpolator", lambda m, x, y, a: m.BarycentricInterpolator(x, y, axis=a)),
    ("make_interp_spline", lambda m, x, y, a: m.make_interp_spline(x, y, k=3, axis=a)),
    ("make_interp_spline k=0", lambda m, x, y, a: m.make_interp_spline(x, y, k=0, axis=a)),
]


@pytest.mark.parametrize("name,make", AXIS_CASES, ids=[c[0] for c in AXIS_CASES])
@pytest.mark.parametrize("axis", [0, 1, 2, -1])
def test_axis_gives_scipys_shapes_and_values(name, make, axis):
    x = np.array([0.0, 0.4, 1.1, 1.9, 2.5, 3.2, 4.0])
    y = RNG.normal(size=(7, 2, 2))
    y = np.moveaxis(y, 0, axis)  # the data along `axis`; 4 numbers per point
    ours, theirs = make(casteljau, x, y, axis), make(si, x, y, axis)
    for xq in (1.5, np.linspace(0.5, 3.5, 5), np.linspace(0.5, 3.5, 6).reshape(2, 3)):
        a, b = ours(xq), theirs(xq)
        assert a.shape == b.shape, (name, axis, np.shape(xq), a.shape, b.shape)
        close(a, b)
    if name not in ("BarycentricInterpolator", "make_interp_spline k=0"):  # neither has a derivative in scipy
        xq = np.linspace(0.5, 3.5, 5)
        for d, e in ((ours.derivative(), theirs.derivative()), (ours.antiderivative(), theirs.antiderivative())):
            assert d(xq).shape == e(xq).shape
        close(ours.derivative()(xq), theirs.derivative()(xq))
        close(ours.antiderivative()(xq), theirs.antiderivative()(xq))
        close(ours.integrate(0.5, 3.0), theirs.integrate(0.5, 3.0))


def test_bspline_axis_and_coefficients_as_scipy():
    t = np.r_[[0.0] * 3, 0.3, 0.6, [1.0] * 3]
    c = RNG.normal(size=(2, 5, 2))  # the coefficients along axis 1
    ours, theirs = casteljau.BSpline(t, c, 2, axis=1), si.BSpline(t, c, 2, axis=1)
    assert ours.c.shape == theirs.c.shape and ours.axis == theirs.axis
    xq = np.linspace(-0.2, 1.2, 8).reshape(2, 4)
    for nu in range(3):
        a, b = ours(xq, nu), theirs(xq, nu)
        assert a.shape == b.shape == (2, 2, 4, 2)
        close(a, b)
    for d, e in ((ours.derivative(), theirs.derivative()), (ours.antiderivative(), theirs.antiderivative())):
        assert d.c.shape[1:] == e.c.shape[1:] and d(xq).shape == e(xq).shape  # scipy pads c with zeros
        close(d(xq), e(xq))
    with pytest.raises(ValueError, match=r"^axis: "):
        casteljau.BSpline(t, c, 2, axis=3)


@pytest.mark.parametrize("n", [17, 40, 120])
def test_barycentric_interpolator_at_many_nodes(n):
    # The library's lagrange curve by its barycentric formulas (the Bezier form, refused
    # above 16 nodes, is not on the way); Chebyshev points keep the interpolant itself well
    # conditioned, as scipy's documentation advises.
    xi = 3 * np.cos(np.linspace(0, np.pi, n)) + 1
    yi = np.stack([np.exp(xi / 3), np.sin(2 * xi)], axis=-1)
    ours, theirs = casteljau.BarycentricInterpolator(xi, yi), si.BarycentricInterpolator(xi, yi)
    xq = np.r_[np.linspace(-2, 4, 97), xi[::7]]  # between the nodes and at nodes (exact there)
    close(ours(xq), theirs(xq))
    np.testing.assert_array_equal(ours(xi[::7]), yi[::7])
    if n >= 40:  # the interpolant converges to the functions (closed forms)
        np.testing.assert_allclose(ours(xq)[:, 0], np.exp(xq / 3), rtol=1e-13)
    # Equispaced nodes: both follow the same (ill-conditioned) polynomial near the middle.
    xe = np.linspace(0, 1, 25)
    ours, theirs = casteljau.BarycentricInterpolator(xe, np.sin(xe)), si.BarycentricInterpolator(xe, np.sin(xe))
    close(ours(np.linspace(0.3, 0.7, 9)), theirs(np.linspace(0.3, 0.7, 9)))


# Session 13 (py2): more than 4 values per point, and BarycentricInterpolator's
# derivative, derivatives, set_yi and add_xi.

WIDE = [((9, 7), 0), ((9, 2, 3, 2), 0), ((2, 9, 3, 2), 1), ((2, 3, 2, 9), -1)]


def tail_of(y, axis):
    return np.moveaxis(y, axis, 0).shape[1:]


@pytest.mark.parametrize("shape,axis", WIDE, ids=[f"{s}-axis{a}" for s, a in WIDE])
def test_wide_values_as_scipy(shape, axis):
    # y with 7 and 12 numbers per point (the library's curves have at most 4): values,
    # derivatives, antiderivatives, integrals and coefficients against scipy 1.10, shapes
    # included. not-a-knot's derivatives at 1e-10: the library's slopes (see above).
    y = RNG.normal(size=shape)
    tail = tail_of(y, axis)
    yp = np.moveaxis(y.copy(), axis, 0)
    yp[-1] = yp[0]
    yp = np.moveaxis(yp, 0, axis)
    inside = np.linspace(X[0], X[-1], 23)
    for bc in ("not-a-knot", "natural", "clamped", "periodic", ((1, RNG.normal(size=tail)), (2, RNG.normal(size=tail))),
               ("not-a-knot", (1, RNG.normal(size=tail)))):
        data = yp if isinstance(bc, str) and bc == "periodic" else y
        ours, theirs = (m.CubicSpline(X, data, axis=axis, bc_type=bc) for m in (casteljau, si))
        rel = REL
        close(ours(XS), theirs(XS))
        close(ours(XS, 1), theirs(XS, 1), rel=rel)
        close(ours.c, theirs.c, rel=rel)
        close(ours.derivative()(XS), theirs.derivative()(XS), rel=rel)
        close(ours.antiderivative()(inside), theirs.antiderivative()(inside))
        close(ours.integrate(X[1], X[-2]), theirs.integrate(X[1], X[-2]))
    for name in ("PchipInterpolator", "Akima1DInterpolator"):
        ours, theirs = getattr(casteljau, name)(X, y, axis=axis), getattr(si, name)(X, y, axis=axis)
        close(ours(XS), theirs(XS))  # Akima: NaN outside, both
        close(ours.derivative()(inside), theirs.derivative()(inside))
        close(ours.integrate(X[1], X[-2]), theirs.integrate(X[1], X[-2]))
    for k in (0, 1, 2, 3, 5):
        ours, theirs = casteljau.make_interp_spline(X, y, k=k, axis=axis), si.make_interp_spline(X, y, k=k, axis=axis)
        close(ours(XS), theirs(XS))
        if k:
            close(ours.derivative()(XS), theirs.derivative()(XS))
            close(ours.antiderivative()(inside), theirs.antiderivative()(inside))
            close(ours.integrate(X[1], X[-2]), theirs.integrate(X[1], X[-2]))
    ours, theirs = (m.make_interp_spline(X, y, k=3, bc_type="natural", axis=axis) for m in (casteljau, si))
    close(ours(XS), theirs(XS))
    close(ours.c, theirs.c)
    t = np.r_[0, 0.5, 1, 2, 3.5, 4, 5, 6, 7.5]  # unclamped: 5 coefficients along axis
    c = np.moveaxis(RNG.normal(size=(5,) + tail), 0, axis)
    ours, theirs = casteljau.BSpline(t, c, 3, axis=axis), si.BSpline(t, c, 3, axis=axis)
    xs = np.linspace(0, 7, 29)
    for nu in range(3):
        close(ours(xs, nu), theirs(xs, nu))
    close(ours.antiderivative()(xs), theirs.antiderivative()(xs))
    close(ours.integrate(1.5, 5.5), theirs.integrate(1.5, 5.5))
    # Inside the nodes' hull: the degree-8 polynomial on random nodes (see above).
    ours, theirs = casteljau.BarycentricInterpolator(X, y, axis=axis), si.BarycentricInterpolator(X, y, axis=axis)
    close(ours(inside), theirs(inside), rel=1e-9)
    import pickle

    again = pickle.loads(pickle.dumps(casteljau.CubicSpline(X, y, axis=axis)))
    assert type(again) is casteljau.CubicSpline
    close(again(XS), si.CubicSpline(X, y, axis=axis)(XS))


def test_periodic_antiderivative_does_not_extrapolate_as_scipy():
    # scipy's PPoly.antiderivative: extrapolate='periodic' becomes False (NaN outside); ours
    # continued it periodically.
    xp = np.linspace(0, 6, 9)
    yp = np.sin(xp)
    yp[-1] = yp[0]
    a, b = (m.CubicSpline(xp, yp, bc_type="periodic").antiderivative() for m in (casteljau, si))
    assert a.extrapolate is False and b.extrapolate is False
    close(a([-1.0, 3.0, 7.0]), b([-1.0, 3.0, 7.0]))


def lebesgue(xi, x):
    """The Lebesgue function sum |l_i(x)| of the nodes xi at x (numpy, from the weights
    1 / prod (x_i - x_j)): the factor by which rounding in the data or the formula can grow."""
    w = np.array([1.0 / np.prod(xi[i] - np.delete(xi, i)) for i in range(len(xi))])
    d = x[:, None] - xi[None, :]
    d[d == 0] = np.finfo(float).tiny
    return np.abs(w / d).sum(axis=1) / np.abs((w / d).sum(axis=1))


def test_barycentric_derivatives_as_krogh():
    # scipy 1.10's BarycentricInterpolator has no derivatives (scipy 1.11's does, with the
    # shapes of KroghInterpolator's): the same polynomial's derivatives by scipy's
    # KroghInterpolator (Newton form) on 8 random nodes, all orders (der=None: n of them),
    # shapes for scalar, vector and 2-D x and axis=1, orders beyond the degree 0.
    xi = np.sort(RNG.random(8)) * 4
    yi = RNG.normal(size=(8, 2))
    ours, theirs = casteljau.BarycentricInterpolator(xi, yi), si.KroghInterpolator(xi, yi)
    xq = np.linspace(-0.5, 4.5, 13)
    a, b = ours.derivatives(xq), theirs.derivatives(xq)
    assert a.shape == b.shape == (8, 13, 2)
    for k in range(8):  # each order against its own size (the 7th is a constant near 1e4)
        close(a[k], b[k], rel=1e-13 * 10**k)
    assert ours.derivatives(1.3, der=10).shape == theirs.derivatives(1.3, der=10).shape == (10, 2)
    assert not ours.derivatives(1.3, der=10)[8:].any()
    close(ours.derivative(xq, 2), theirs.derivative(xq, 2), rel=1e-11)
    assert not ours.derivative(xq, 9).any() and ours.derivative(xq, 9).shape == (13, 2)
    y3 = RNG.normal(size=(2, 8, 3))
    ours, theirs = casteljau.BarycentricInterpolator(xi, y3, axis=1), si.KroghInterpolator(xi, y3, axis=1)
    xq2 = xq[:12].reshape(3, 4)
    for x in (xq2, 1.7):
        a, b = ours.derivatives(x, der=3), theirs.derivatives(x, der=3)
        assert a.shape == b.shape
        close(a, b, rel=1e-11)
        close(ours.derivative(x), theirs.derivative(x), rel=1e-12)
    with pytest.raises(casteljau.Error, match=r"^der: must be an integer >= 0"):
        ours.derivative(0.5, -1)


@pytest.mark.parametrize("n", [40, 120])
def test_barycentric_derivatives_at_many_chebyshev_nodes(n):
    # The interpolant of exp on n Chebyshev points is exp to rounding, so are its
    # derivatives up to rounding amplified by about n^2 per order (Markov's inequality):
    # orders 0..2 against exp within 4 eps n^(2k) relative (measured: at most 1 eps n^(2k)).
    xi = np.cos(np.linspace(0, np.pi, n))
    p = casteljau.BarycentricInterpolator(xi, np.exp(xi))
    xq = np.linspace(-1, 1, 21)  # outside, the rounding grows exponentially with n
    d = p.derivatives(xq, der=3)
    eps = np.finfo(float).eps
    for k in range(3):
        np.testing.assert_allclose(d[k], np.exp(xq), rtol=4 * eps * max(n ** (2 * k), 30))
    close(p.derivative(xq, 1), d[1], rel=0)


def test_barycentric_values_at_many_random_nodes():
    # 30 random nodes: scipy and ours evaluate the same polynomial with rounding bounded by
    # about n eps times the Lebesgue function (Higham 2004, the second barycentric formula
    # on these nodes); it is computed here from the nodes and sets each point's tolerance.
    xi = np.sort(RNG.random(30)) * 2 - 1
    yi = np.cos(3 * xi)
    xq = np.linspace(-1, 1, 41)
    ours, theirs = casteljau.BarycentricInterpolator(xi, yi)(xq), si.BarycentricInterpolator(xi, yi)(xq)
    bound = 4 * 30 * np.finfo(float).eps * lebesgue(xi, xq) * np.max(np.abs(yi))
    assert np.all(np.abs(ours - theirs) <= bound), np.max(np.abs(ours - theirs) / bound)


def test_barycentric_set_yi_and_add_xi():
    # Against scipy's interpolator made on all the nodes at once (scipy 1.10's own add_xi
    # flips the sign of the old nodes' weights and answers another polynomial: 12.48938
    # for 12.48958, KroghInterpolator's and ours, in a trial with 6 random nodes and one
    # added; not the oracle).
    xi = np.sort(RNG.random(6))
    y = RNG.normal(size=(2, 6, 3))
    ours = casteljau.BarycentricInterpolator(xi, y, axis=1)
    x2, y2 = RNG.random(3) + 1, RNG.normal(size=(2, 3, 3))
    ours.add_xi(x2, y2)
    theirs = si.BarycentricInterpolator(np.r_[xi, x2], np.concatenate([y, y2], axis=1), axis=1)
    xq = np.linspace(0, 2, 7).reshape(7, 1)
    assert ours(xq).shape == theirs(xq).shape == (2, 7, 1, 3)
    close(ours(xq), theirs(xq), rel=1e-9)
    assert (ours.n, ours.r) == (9, 6)
    y3 = RNG.normal(size=(9, 5))  # new values, another axis and shape
    ours.set_yi(y3, axis=0)
    close(ours(xq), si.BarycentricInterpolator(np.r_[xi, x2], y3)(xq), rel=1e-9)
    # Nodes first, values later (scipy's order of calls).
    p = casteljau.BarycentricInterpolator(xi)
    with pytest.raises(casteljau.Error, match=r"^yi: not set"):
        p(0.5)
    p.add_xi([2.0])
    p.set_yi(np.arange(7.0) ** 2)
    close(p(np.r_[0.5, 1.5]), si.KroghInterpolator(np.r_[xi, 2.0], np.arange(7.0) ** 2)(np.r_[0.5, 1.5]), rel=1e-12)
    with pytest.raises(casteljau.Error, match=r"^yi: required"):
        p.add_xi([3.0])
    with pytest.raises(casteljau.Error, match=r"^yi: must have 1 axes \(values of shape \(\) along axis 0\)"):
        p.add_xi([3.0], [[1.0, 2.0]])
    with pytest.raises(casteljau.Error, match=r"^yi: 7 values along axis 0 but xi has 6"):
        casteljau.BarycentricInterpolator(xi).set_yi(np.arange(7.0))


def test_roots_of_several_values_per_point_as_scipy():
    # scipy's PPoly.roots and solve on data of several values per point: an object array of
    # y's trailing shape, one array of roots per value (we raised). Columns with no
    # rounding-size end coefficients (see test_roots_of_lower_degree_data_have_no_rounding_roots).
    x = np.linspace(0, 4, 9)
    cols = [np.cos(x), np.sin(x) - 0.2, np.cos(2 * x), np.sin(3 * x) + 0.1, np.exp(-x) - 0.5, x * np.cos(x) - 0.3]
    y = np.stack(cols, axis=-1).reshape(9, 2, 3)
    for name, axis in (("CubicSpline", 0), ("PchipInterpolator", 2), ("Akima1DInterpolator", 1)):
        data = np.moveaxis(y, 0, axis)
        ours, theirs = getattr(casteljau, name)(x, data, axis=axis), getattr(si, name)(x, data, axis=axis)
        for a, b in ((ours.roots(), theirs.roots()), (ours.solve(0.5, extrapolate=False),
                                                      theirs.solve(0.5, extrapolate=False))):
            assert a.dtype == b.dtype == object and a.shape == b.shape
            for u, v in zip(a.flat, b.flat):
                close(u, np.sort(v), rel=1e-10)


# Session 14: BarycentricInterpolator's list of orders and given weights (scipy 1.11; Debian
# has scipy 1.10: exact rational arithmetic is the oracle, and scipy 1.10 where it has the
# form: krogh_interpolate's list of orders, the weights as an attribute).

def _exact_lagrange_derivatives(xi, yi, x, orders):
    """The interpolating polynomial's derivatives at x, exactly: Newton's divided
    differences in fractions, expanded into power coefficients, differentiated."""
    from fractions import Fraction as Fr
    xs, ys = [Fr(float(v)) for v in xi], [Fr(float(v)) for v in yi]
    n = len(xs)
    dd = list(ys)
    for j in range(1, n):
        for i in range(n - 1, j - 1, -1):
            dd[i] = (dd[i] - dd[i - 1]) / (xs[i] - xs[i - j])
    coef = [Fr(0)] * n  # power coefficients, lowest first: Horner on the Newton form
    for i in range(n - 1, -1, -1):
        new = [Fr(0)] * n
        for k in range(n - 1):
            new[k + 1] += coef[k]
            new[k] -= xs[i] * coef[k]
        new[0] += dd[i]
        coef = new
    out = []
    for k in orders:
        c = list(coef)
        for _ in range(k):
            c = [j * c[j] for j in range(1, len(c))] or [Fr(0)]
        t = Fr(float(x))
        out.append(float(sum(cj * t**j for j, cj in enumerate(c))))
    return np.array(out)


def test_barycentric_derivatives_with_a_list_of_orders():
    # scipy's documentation: der "a list of derivatives to evaluate", d[j] the der[j]-th
    # (scipy computes it as derivatives(x, max(der) + 1)[der], in barycentric_interpolate
    # and krogh_interpolate, which scipy 1.10 has). Orders above the degree are 0.
    xi = np.sort(RNG.random(7)) * 3 - 1
    yi = RNG.normal(size=7)
    ours = casteljau.BarycentricInterpolator(xi, yi)
    orders = [3, 0, 1, 9, 3]
    for x in (0.4, -1.3, 2.7):
        got = ours.derivatives(x, der=orders)
        want = _exact_lagrange_derivatives(xi, yi, x, orders)
        assert got.shape == (5,)
        for k, g, w in zip(orders, got, want):
            assert abs(g - w) <= 1e-13 * 10**k * max(1.0, abs(w)), (x, k, g, w)
    xq = np.linspace(-1.5, 2.5, 12).reshape(3, 4)
    y3 = RNG.normal(size=(2, 7, 3))
    for y, axis in ((yi, 0), (y3, 1)):
        ours = casteljau.BarycentricInterpolator(xi, y, axis=axis)
        a = ours.derivatives(xq, der=np.array([2, 0]))
        b = si.krogh_interpolate(xi, y, xq, der=[2, 0], axis=axis)
        assert a.shape == b.shape
        close(a, b, rel=1e-11)
        np.testing.assert_array_equal(a[1], ours(xq))  # order 0 is the call
    with pytest.raises(casteljau.Error, match=r"^der\[1\]: must be an integer >= 0, got -1"):
        ours.derivatives(0.5, der=[1, -1])
    with pytest.raises(casteljau.Error, match=r"^der: an empty list"):
        ours.derivatives(0.5, der=[])


def test_barycentric_given_weights():
    # wi (scipy 1.11): the weights of the second barycentric formula, used as given.
    # Chebyshev points of the second kind have the closed-form weights (-1)^i (halved at
    # the ends) [BerrutTrefethen04]: the same polynomial as the computed weights; against
    # the exact Lagrange derivatives.
    n = 12
    xi = np.cos(np.arange(n) * np.pi / (n - 1))
    yi = np.stack([np.exp(xi), np.sin(3 * xi)], axis=-1)
    w = (-1.0) ** np.arange(n)
    w[[0, -1]] /= 2
    given, computed = casteljau.BarycentricInterpolator(xi, yi, wi=w), casteljau.BarycentricInterpolator(xi, yi)
    np.testing.assert_array_equal(given.wi, w)
    xq = np.r_[np.linspace(-1, 1, 9), xi[::5]]
    close(given(xq), computed(xq), rel=1e-14)
    np.testing.assert_array_equal(given(xi[::5]), yi[::5])  # exact at the nodes
    d = given.derivatives(xq, der=4)
    for j, x in enumerate(xq[:9]):
        want = _exact_lagrange_derivatives(xi, yi[:, 0], x, range(4))
        for k in range(4):
            assert abs(d[k, j, 0] - want[k]) <= 1e-13 * 10**k * max(1.0, abs(want[k])), (x, k)
    # Any weights: scipy's formula with them (a rational interpolant, not a polynomial),
    # against scipy 1.10 given the same weights as its attribute and against the formula
    # in fractions; derivatives as scipy 1.11's, the formula on D^k yi (D the weights'
    # differentiation matrix, [BerrutTrefethen04, (9.4), (9.5)]), in fractions.
    from fractions import Fraction as Fr
    xi = np.sort(RNG.random(6)) * 2
    yi = RNG.normal(size=6)
    w = RNG.uniform(0.5, 2, size=6) * (-1.0) ** np.arange(6)
    ours = casteljau.BarycentricInterpolator(xi, yi, wi=w, random_state=3)
    theirs = si.BarycentricInterpolator(xi, yi)
    theirs.wi = w
    xq = np.r_[np.linspace(-0.5, 2.5, 11), xi[2]]
    close(ours(xq), theirs(xq), rel=1e-13)
    X, W = [Fr(float(v)) for v in xi], [Fr(float(v)) for v in w]
    D = [[(W[j] / W[i]) / (X[i] - X[j]) if i != j else Fr(0) for j in range(6)] for i in range(6)]
    for i in range(6):
        D[i][i] = -sum(D[i])
    y = [Fr(float(v)) for v in yi]
    for k in range(3):
        if k:
            y = [sum(D[i][j] * y[j] for j in range(6)) for i in range(6)]
        got = ours.derivative(xq, k)
        for x, g in zip(xq, got):
            t = Fr(float(x))
            if t in X:
                want = float(y[X.index(t)])
            else:
                c = [W[i] / (t - X[i]) for i in range(6)]
                want = float(sum(ci * yy for ci, yy in zip(c, y)) / sum(c))
            assert abs(g - want) <= 1e-12 * max(1.0, abs(want)), (k, x, g, want)
    # The computed weights are scipy's formula (its random order of the product aside).
    close(casteljau.BarycentricInterpolator(xi, yi).wi, si.BarycentricInterpolator(xi, yi).wi, rel=1e-13)
    with pytest.raises(casteljau.Error, match=r"^wi: must have one weight per node"):
        casteljau.BarycentricInterpolator(xi, yi, wi=w[:5])
    with pytest.raises(casteljau.Error, match=r"^wi\[2\]: must be a finite nonzero number, got nan"):
        casteljau.BarycentricInterpolator(xi, yi, wi=np.r_[w[:2], np.nan, w[3:]])
    with pytest.raises(casteljau.Error, match=r"^wi: the interpolator was given its weights"):
        ours.add_xi([3.0], [1.0])
    with pytest.raises(casteljau.Error, match=r"^x\[1\]: must be a finite number"):
        ours([0.5, np.nan])


# Session 14: not-a-knot splines against the exact solve. The library's not-a-knot ends
# (from 6 points on) take the first two and the last two pieces as the one cubic each
# that the condition makes them (curves/cubic_spline.hpp); the textbook end row lost tens
# to hundreds of ulps in the end slopes when adjacent spacings differ much, which the end
# pieces' cubic coefficients amplify far outside the domain.

def _exact_not_a_knot(x, y):
    """The not-a-knot spline's slopes at the params in rational arithmetic (the system of
    scipy's CubicSpline: C^2 rows and its not-a-knot end rows, solved exactly), and its
    exact value (order nu) at t: the end pieces continued outside."""
    from fractions import Fraction as Fr
    X, Y = [Fr(float(v)) for v in x], [Fr(float(v)) for v in y]
    n = len(X) - 1
    h = [X[i + 1] - X[i] for i in range(n)]
    d = [(Y[i + 1] - Y[i]) / h[i] for i in range(n)]
    a, b, c, r = [Fr(0)] * (n + 1), [Fr(0)] * (n + 1), [Fr(0)] * (n + 1), [Fr(0)] * (n + 1)
    for i in range(1, n):
        a[i], b[i], c[i], r[i] = h[i], 2 * (h[i - 1] + h[i]), h[i - 1], 3 * (h[i] * d[i - 1] + h[i - 1] * d[i])
    s0, s1 = h[0] + h[1], h[n - 1] + h[n - 2]
    b[0], c[0], r[0] = h[1], s0, ((h[0] + 2 * s0) * h[1] * d[0] + h[0] ** 2 * d[1]) / s0
    b[n], a[n], r[n] = h[n - 2], s1, (h[n - 1] ** 2 * d[n - 2] + (2 * s1 + h[n - 1]) * h[n - 2] * d[n - 1]) / s1
    for i in range(1, n + 1):
        f = a[i] / b[i - 1]
        b[i] -= f * c[i - 1]
        r[i] -= f * r[i - 1]
    s = [Fr(0)] * (n + 1)
    s[n] = r[n] / b[n]
    for i in range(n - 1, -1, -1):
        s[i] = (r[i] - c[i] * s[i + 1]) / b[i]

    def value(t: float, nu: int) -> float:
        i = 0 if t < x[1] else n - 1  # the end pieces (t outside, or in the first piece)
        co = [Y[i], s[i], (3 * d[i] - 2 * s[i] - s[i + 1]) / h[i], (s[i] + s[i + 1] - 2 * d[i]) / h[i] ** 2]
        for _ in range(nu):
            co = [k * co[k] for k in range(1, len(co))]
        u = Fr(float(t)) - X[i]
        return float(sum(ck * u**k for k, ck in enumerate(co)))

    return np.array([float(v) for v in s]), value


def _not_a_knot_data(kind):
    rng = np.random.default_rng(1416)
    if kind == "200 random points":  # session 13's measurement: offset 1000
        x = np.sort(rng.random(200)) * 10 + 1000
        return x, np.sin(x) + rng.random(200)
    if kind == "spacings 1e-3 to 1":  # adjacent spacings up to 10^3 apart, log-uniform
        h = 10.0 ** rng.uniform(-3, 0, 29)
    else:  # "ratio 1e3 at both ends": spacings 1, 1e-3, 1, ... and mirrored
        h = np.where(np.arange(29) % 2 == 0, 1.0, 1e-3) * (1 + 0.2 * rng.random(29))
        h[-3:] = h[:3][::-1]
    x = 1000 + np.r_[0, np.cumsum(h)]
    return x, np.cos(x) + np.linspace(0, 3, 30) + 0.1 * rng.random(30)


@pytest.mark.parametrize("kind", ["200 random points", "spacings 1e-3 to 1", "ratio 1e3 at both ends"])
def test_not_a_knot_against_the_exact_solve(kind):
    x, y = _not_a_knot_data(kind)
    exact, value = _exact_not_a_knot(x, y)
    ours, theirs = casteljau.CubicSpline(x, y), si.CubicSpline(x, y)
    # The library's slopes (read exactly at the params by the eval command).
    slopes = np.asarray(casteljau.run("eval", curve=casteljau.CubicSpline(params=x, points=y[:, None],
                                                                          boundary="not-a-knot"),
                                      t=x, derivatives=1).derivatives).reshape(-1)
    ulps = np.abs(slopes - exact) / np.spacing(np.abs(exact))
    ends = ulps[[0, 1, -2, -1]]
    assert ends.max() <= 256, ends
    # 1e-12 relative pointwise, values and derivatives, to 10 domain lengths out: against
    # the exact spline, and against scipy up to scipy's own error there (scipy's pivoted
    # solve has its own: up to 1e-12 relative on these data).
    L = x[-1] - x[0]
    xs = np.r_[x[0] - L * np.array([10, 3, 1, 0.1, 1e-3]), x[-1] + L * np.array([1e-3, 0.1, 1, 3, 10])]
    for nu in range(4):
        want = np.array([value(t, nu) for t in xs])
        a, b = ours(xs, nu), theirs(xs, nu)
        np.testing.assert_allclose(a, want, rtol=1e-12, atol=0, err_msg=f"nu={nu}")
        assert np.all(np.abs(a - b) <= 1e-12 * np.abs(b) + np.abs(b - want)), nu


def test_ppoly_coefficient_constructor_refused():
    """scipy's PPoly(c, x) is not supported: a TypeError saying so, not an AttributeError."""
    with pytest.raises(TypeError, match=r"PPoly\(c, x\) is not supported"):
        casteljau.PPoly(np.array([[1.0], [0.0]]), np.array([0.0, 1.0]))
