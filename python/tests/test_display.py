# python/tests/test_display.py - what Jupyter shows of every result (issue
# 32).  HTML is checked by a strict reading (html.parser: every tag closed
# in order) and its cells read back as the numbers of the result: the
# double pendulum's modes w^2 = (g/l)(2 -+ sqrt 2) (Goldstein ch. 6, equal
# masses and lengths), the cart-pendulum's A (its upright eigenvalue
# sqrt(g (M + m)/(M l))), the oscillator's x = cos(w t).  LaTeX is compared
# with what the command line prints for the same command (`qdot CMD
# --format latex`), entry by entry with `qdot print --format latex`.
import base64
import html.parser
import math
import os
import re
import subprocess

import numpy as np
import pytest

import qdot
from conftest import EXAMPLES
from test_commands import BUILD, OSCILLATOR

VOID = {"img", "br", "hr", "meta", "input", "col"}


class _Strict(html.parser.HTMLParser):
    """Tags nested and closed in order; the text of each cell (td, th)."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.cells, self.imgs, self._cell = [], [], [], None

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.imgs.append(dict(attrs))
        if tag in VOID:
            return
        self.stack.append(tag)
        if tag in ("td", "th"):
            self._cell = []

    def handle_startendtag(self, tag, attrs):
        if tag == "img":
            self.imgs.append(dict(attrs))

    def handle_endtag(self, tag):
        assert self.stack and self.stack[-1] == tag, ("</%s> closes %s" % (tag, self.stack))
        self.stack.pop()
        if tag in ("td", "th") and self._cell is not None:
            self.cells.append("".join(self._cell).strip())
            self._cell = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def parsed(text):
    """The strict reading of an HTML fragment (it must be one)."""
    assert isinstance(text, str) and text.startswith("<")
    p = _Strict()
    p.feed(text)
    p.close()
    assert p.stack == [], "unclosed: %s" % p.stack
    return p


def numbers(cells):
    out = []
    for c in cells:
        try:
            out.append(float(c))
        except ValueError:
            pass
    return np.array(out)


def cli_text(*args):
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        pytest.skip("no build/qdot to compare with")
    run = subprocess.run([exe, *args], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return run.stdout


def rows(latex):
    """The formula rows of a LaTeX display: $$, environments, comments and
    blanks dropped, split at \\\\ (so an align and a gathered compare)."""
    body = latex.strip()
    if body.startswith("$$"):
        body = body[2:-2]
    body = "\n".join(ln for ln in body.splitlines() if not ln.lstrip().startswith("%"))
    body = re.sub(r"\\(begin|end)\{(align\*?|aligned|gathered)\}", "", body)
    return [r.strip() for r in re.split(r"\\\\", body) if r.strip()]


DOUBLE = os.path.join(EXAMPLES, "double_pendulum.qd")
CART = os.path.join(EXAMPLES, "cart_pendulum.qd")


@pytest.fixture(scope="module")
def dp():
    return qdot.Model.load(DOUBLE)


# ---- LaTeX: the command line's rendering, row for row ------------------------

def test_eom_and_hamiltonian_latex_are_the_clis(dp):
    assert rows(dp.eom()._repr_latex_()) == rows(cli_text("eom", DOUBLE, "--format", "latex"))
    assert rows(dp.hamiltonian()._repr_latex_()) == rows(
        cli_text("hamiltonian", DOUBLE, "--format", "latex"))
    assert dp.eom()._repr_latex_().startswith("$$")


def test_command_latex_is_the_clis_and_hides_the_table(tmp_path):
    kepler = os.path.join(EXAMPLES, "kepler_polar.qd")
    k = qdot.Model.load(kepler)
    for out, args in ((k.routh("theta"), ("routh", kepler, "--ignore", "theta")),
                      (k.hj(), ("hj", kepler)),
                      (k.bracket("r", "p_r"), ("bracket", kepler, "r", "p_r")),
                      (k.integrals(), ("integrals", kepler))):
        assert rows(out._repr_latex_()) == rows(cli_text(*args, "--format", "latex")), args
        assert out._repr_html_() is None           # the formulas show, not a table
        parsed(out.html())                         # the table is still there to ask for


def test_integrals_latex_has_each_integral_and_its_verdict():
    # Kepler's polar model: theta is cyclic, p_theta = m r^2 theta' (the areal
    # law) is conserved, and so is h = T + V (Goldstein ch. 1, Desloge ch. 59)
    k = qdot.Model.load(os.path.join(EXAMPLES, "kepler_polar.qd"))
    r = [x for x in rows(k.integrals()._repr_latex_()) if "gathered" not in x]
    assert r[0] == "p_{\\theta} &= m r^{2} \\dot{\\theta} && \\text{conserved}", r
    assert r[1].startswith("h &= ") and r[1].endswith("\\text{conserved}") and len(r) == 2, r
    # an integral proposed that is not one is said to be not conserved
    r = rows(qdot.Model(open(os.path.join(EXAMPLES, "kepler_polar.qd")).read() +
                        "\nintegral radial: m*r'\n").integrals()._repr_latex_())
    assert "\\text{radial} &= m \\dot{r} && \\text{not conserved}" in r, r


def test_statespace_latex_entries_are_the_librarys():
    ss = qdot.Model.load(CART).linearize(about={"th": 0})
    tex = ss._repr_latex_()
    assert tex.startswith("$$") and tex.endswith("$$") and ss._repr_html_() is None
    mats = re.findall(r"\\begin\{pmatrix\}(.*?)\\end\{pmatrix\}", tex)
    # the state column, A, the state column, B, the input column
    assert len(mats) == 5
    A = [r.split(" & ") for r in mats[1].split(" \\\\ ")]
    B = [r.split(" & ") for r in mats[3].split(" \\\\ ")]
    for printed, exact in ((A, ss.A_exact), (B, ss.B_exact)):
        assert len(printed) == len(exact)
        for prow, erow in zip(printed, exact):
            for p, e in zip(prow, erow):
                assert p == cli_text("print", e, "--format", "latex").strip(), (p, e)
    # g (m/M + 1)/l at the cart's numbers is the upright eigenvalue squared
    assert ss.A[3, 1] == pytest.approx(ss.eigenvalues.real.max() ** 2, rel=1e-12)


# ---- HTML: well formed, and its numbers are the result's -----------------------

def test_modes_table_holds_the_frequencies(dp):
    modes = dp.modes()
    p = parsed(modes._repr_html_())
    w2 = [m.omega2 for m in modes]
    g = 9.81
    assert w2 == pytest.approx([g * (2 - math.sqrt(2)), g * (2 + math.sqrt(2))], rel=1e-9)
    vals = numbers(p.cells)
    for m in modes:  # omega^2, omega and the shape, each cell to 10 digits
        for v in [m.omega2, m.omega, *m.shape.values()]:
            assert np.min(np.abs(vals - v)) <= 1e-9 * max(1, abs(v)), v
    assert "theta1" in p.cells and "omega^2" in p.cells
    assert "omega = 2.397199" in repr(modes) and "theta1 = 0" in repr(modes)
    parsed(modes[0]._repr_html_())


def test_damped_modes_show_the_eigenvalues():
    # x'' + 2 c x' + w^2 x = 0: s = -c +- i sqrt(w^2 - c^2), here c = 1/2, w = 2
    m = qdot.Model("coordinates x\nT = x'^2/2\nV = 2*x^2\ndissipation = x'^2/2\n")
    modes = m.modes(about={"x": 0})
    p = parsed(modes._repr_html_())
    vals = numbers(p.cells)
    assert np.min(np.abs(vals + 0.5)) < 1e-9
    assert np.min(np.abs(np.abs(vals) - math.sqrt(4 - 0.25))) < 1e-9
    assert "eigenvalues" in repr(modes)


def test_equilibria_table(dp):
    eqs = dp.equilibria()
    p = parsed(eqs._repr_html_())
    kinds = [e.kind for e in eqs]
    assert [c for c in p.cells if c in ("minimum", "saddle", "maximum")] == kinds
    assert np.min(np.abs(numbers(p.cells) - math.pi)) < 1e-9   # theta = pi, a saddle
    assert "theta1 = 0, theta2 = pi" in p.cells                # the exact values, as printed
    assert repr(eqs).startswith("<qdot.Equilibria 4: minimum")
    parsed(eqs[0]._repr_html_())


def test_statespace_and_lqr_tables():
    ss = qdot.Model.load(CART).linearize(about={"th": 0})
    p = parsed(ss.html())
    assert "th'" in p.cells                          # escaped as &#x27;, read back
    vals = numbers(p.cells)
    for v in ss.A.ravel():
        assert np.min(np.abs(vals - v)) <= 1e-9 * max(1, abs(v))
    lq = ss.lqr(np.diag([1, 10, 1, 1]), 0.1)
    pl = parsed(lq._repr_html_())
    for v in lq.K.ravel():
        assert np.min(np.abs(numbers(pl.cells) - v)) <= 1e-9 * abs(v)
    assert repr(lq).startswith("Lqr(K=[[") and "eigenvalues" in repr(ss)
    d = qdot.lqr([[0, 1], [0, 0]], [[0], [1]], "Q = diag(1, 1), R = 1")
    assert np.min(np.abs(numbers(parsed(d._repr_html_()).cells) - math.sqrt(3))) < 1e-9


def test_output_tables_orbit_sweep_check():
    kep = qdot.Model.load(os.path.join(EXAMPLES, "kepler_polar.qd"))
    o = kep.orbit("theta")
    assert o._repr_latex_() is None
    p = parsed(o._repr_html_())
    assert "radial_period" in p.cells
    assert np.min(np.abs(numbers(p.cells) - o.radial_period)) < 1e-9
    spring = qdot.Model(OSCILLATOR)
    sw = spring.sweep(1, "final", grid="k=1:4:2", rtol=1e-12)
    ps = parsed(sw._repr_html_())
    assert ps.cells[ps.cells.index("k"):ps.cells.index("k") + 3] == sw.columns
    # x(1) = cos(sqrt(k/m)) for k = 1 and 4, m = 2
    for k in (1, 4):
        assert np.min(np.abs(numbers(ps.cells) - math.cos(math.sqrt(k / 2)))) < 1e-9
    pc = parsed(spring.check()._repr_html_())
    assert "ok" in pc.cells


def test_run_shows_its_plot_summary_and_rows():
    spring = qdot.Model(OSCILLATOR)
    r = spring.simulate(2, rtol=1e-12, dt=0.5, events=["x = 0"])
    p = parsed(r._repr_html_())
    assert len(p.imgs) == 1
    src = p.imgs[0]["src"]
    assert src.startswith("data:image/png;base64,")     # inline: no file, no network
    assert base64.b64decode(src.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    vals = numbers(p.cells)
    w = math.sqrt(1.5)
    for t in (0.5, 1.0, 1.5, 2.0):
        assert np.min(np.abs(vals - math.cos(w * t))) < 1e-9      # x = cos(w t)
    assert "dop853" in p.cells
    pe = parsed(r.events[0]._repr_html_())
    assert np.min(np.abs(numbers(pe.cells) - math.pi / 2 / w)) < 1e-9   # the first zero
    assert repr(r.events[0]).startswith("<qdot.Table 1 rows: t, x")
    sec = spring.poincare("x = 0, x' > 0", 2, rtol=1e-12)
    ps = parsed(sec._repr_html_())
    assert "qdot poincare" in sec._repr_html_()
    assert np.min(np.abs(numbers(ps.cells) - 1.5 * math.pi / w)) < 1e-6


def test_forms_relativity_fields_and_every_repr(dp):
    f = qdot.quadratic_form("x^2 + 4*x*y + y^2", ["x", "y"])
    assert "indefinite" in parsed(f._repr_html_()).cells
    parsed(qdot.homogeneity("x^2*y", ["x"])._repr_html_())
    parsed(qdot.periods("sin(3*x)", ["x"], [["2*pi"]])._repr_html_())
    lo = qdot.lorentz((0.6, 0, 0))
    assert np.min(np.abs(numbers(parsed(lo._repr_html_()).cells) - 1.25)) < 1e-12   # gamma
    kep = qdot.Model.load(os.path.join(EXAMPLES, "kepler_polar.qd"))
    parsed(kep.orbit("theta").conic._repr_html_())
    g = kep.metric()
    pg = parsed(g._repr_html_())
    assert "m*r^2" in pg.cells
    assert repr(g) == "<qdot.Metric of r, theta: det g = m^2*r^2, orthogonal>"
    # every object a call returns has a repr of its own, not object's
    objs = [dp, dp.eom(), dp.hamiltonian(), dp.equilibria(), dp.equilibria()[0], dp.modes(),
            dp.modes()[0], dp.compile(), dp.codegen(), dp.animate(0.2), dp.simulate(0.2),
            qdot.Model(OSCILLATOR).linearize(), kep.orbit("theta"), f, lo,
            qdot.parse("x^2"), g, kep.flow(period="1"), kep.integrals()]
    for o in objs:
        assert " object at 0x" not in repr(o), type(o)


def test_text_is_escaped():
    # a field's text cannot open a tag of its own: it reads back as text
    from qdot import display
    p = parsed(display.fields({"a<b": "x < y & <script>", "n": [1, 2.5]}))
    assert p.cells == ["a<b", "x < y & <script>", "n", "1", "2.5"]


def test_long_tables_say_what_they_leave_out():
    from qdot import display
    p = parsed(display.table([str(j) for j in range(20)],
                             [[i * 100 + j for j in range(20)] for i in range(30)]))
    assert p.cells[:16] == [str(j) for j in range(16)] and p.cells[16] == ""
    body = p.cells[17:]
    assert body[:17] == [str(j) for j in range(16)] + ["\u2026 4 more"]
    assert body[-1] == "\u2026 18 more rows" and len(body) == 12 * 17 + 1
