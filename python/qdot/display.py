# python/qdot/display.py - what Jupyter shows of a result: HTML tables of
# its numbers (_repr_html_) and LaTeX displays of its formulas
# (_repr_latex_), issue 32.
#
# The numbers are laid out here, never computed: every value is a field the
# library wrote (a command's JSON, a struct it filled).  Formulas are not
# written here either: each is printed by the library's LaTeX printer
# (qd_print with QD_FMT_LATEX, or a command's own LaTeX rendering); this
# file only puts the printed pieces in a matrix or a row.  Every text is
# escaped (html.escape), so a name like "theta1'" or a reason with "<"
# cannot break the page.
"""HTML tables and LaTeX displays for Jupyter (internal module)."""

import html
import numbers

import numpy as np

_ROWS = 12  # rows of a long table shown: the first ones, then how many are left out
_COLS = 16  # columns likewise (a curve's thousand points, a grid's row)
_STYLE = "border-collapse:collapse;text-align:right"
_CELL = "padding:1px 6px;border:1px solid #ccc"


def _esc(text):
    return html.escape(str(text), quote=True)


def number(x):
    """A number as a cell shows it: 10 significant digits, complex as a + bi."""
    if isinstance(x, bool) or isinstance(x, np.bool_):
        return "true" if x else "false"
    if isinstance(x, (complex, np.complexfloating)):
        if x.imag == 0:
            return number(x.real)
        return "%.10g %s %.10gi" % (x.real, "-" if x.imag < 0 else "+", abs(x.imag))
    if isinstance(x, numbers.Integral):
        return str(int(x))
    return "%.10g" % float(x)


def _is_number(x):
    return isinstance(x, (numbers.Number, np.number)) and not isinstance(x, (bool, np.bool_))


class _Raw(str):
    """HTML made here (not a value to escape)."""


def value(x):
    """The HTML of a value: a number, a string (as code), a list or an
    array (a table), a dict (a table of its keys), None (a dash)."""
    if isinstance(x, _Raw):
        return str(x)
    if x is None:
        return "&mdash;"
    if isinstance(x, (bool, np.bool_)):
        return number(x)
    if _is_number(x):
        return number(x)
    if isinstance(x, str):
        return "<code>%s</code>" % _esc(x)
    if isinstance(x, dict):
        return fields(x)
    if isinstance(x, np.ndarray):
        if x.ndim == 1:
            return table(None, [list(x)])
        if x.ndim == 2:
            return table(None, x.tolist())
        return "<code>%s</code>" % _esc(repr(x))
    if isinstance(x, (list, tuple)):
        if not x:
            return "[]"
        if all(isinstance(v, (list, tuple)) for v in x):
            return table(None, [list(v) for v in x])
        if all(_is_number(v) or isinstance(v, str) for v in x):
            return table(None, [list(x)])
        return "<ol>%s</ol>" % "".join("<li>%s</li>" % value(v) for v in x)
    return "<code>%s</code>" % _esc(repr(x))


def table(header, rows, row_names=None, caption=None):
    """A <table>: header (column names or None), rows (lists of values),
    row_names (a name per row or None), caption (text or None).  A long
    table shows its first rows and says how many more there are."""
    width = max((len(r) for r in rows), default=0)
    if width > _COLS:  # the first columns, then how many more
        more = "&hellip; %d more" % (width - _COLS)
        rows = [list(r[:_COLS]) + [_Raw(more)] for r in rows]
        header = list(header[:_COLS]) + [""] if header is not None else None
    out = ['<table style="%s">' % _STYLE]
    if caption:
        out.append("<caption>%s</caption>" % _esc(caption))
    if header is not None:
        lead = "<th></th>" if row_names is not None else ""
        out.append("<thead><tr>%s%s</tr></thead>" % (lead, "".join(
            '<th style="%s">%s</th>' % (_CELL, _esc(h)) for h in header)))
    out.append("<tbody>")
    for i, row in enumerate(rows[:_ROWS]):
        lead = ('<th style="%s">%s</th>' % (_CELL, _esc(row_names[i]))
                if row_names is not None else "")
        out.append("<tr>%s%s</tr>" % (lead, "".join(
            '<td style="%s">%s</td>' % (_CELL, value(v)) for v in row)))
    if len(rows) > _ROWS:
        width = max((len(r) for r in rows), default=1) + (row_names is not None)
        out.append('<tr><td colspan="%d">&hellip; %d more rows</td></tr>'
                   % (width, len(rows) - _ROWS))
    out.append("</tbody></table>")
    return "".join(out)


def fields(mapping, title=None):
    """A two-column table: each key and its value (value above)."""
    rows = "".join('<tr><th style="%s;text-align:left">%s</th><td style="%s">%s</td></tr>'
                   % (_CELL, _esc(k), _CELL, value(v)) for k, v in mapping.items())
    cap = "<caption>%s</caption>" % _esc(title) if title else ""
    return '<table style="%s">%s<tbody>%s</tbody></table>' % (_STYLE, cap, rows)


def block(title, *parts):
    """A titled block of parts (HTML pieces), for a result of several tables."""
    return "<div><strong>%s</strong>%s</div>" % (_esc(title), "".join(
        "<div>%s</div>" % p for p in parts))


def latex_matrix(printed):
    """A pmatrix of LaTeX entries already printed by the library (rows of
    strings): only the layout is made here."""
    return "\\begin{pmatrix}%s\\end{pmatrix}" % " \\\\ ".join(
        " & ".join(row) for row in printed)
