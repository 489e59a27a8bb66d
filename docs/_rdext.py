"""Sphinx directives of the rollingdisk documentation, made at build time from the library
itself (nothing generated is written into docs/):

* ``rollingdisk-cli``: the command-line reference, one section per command with its
  ``--help`` text, from the real parsers (:func:`rollingdisk.cli.app.build_parser`);
* ``rollingdisk-equations``: the paper's printed statements of sections 3 and 4 as math
  (:data:`rollingdisk.symbolic.printed.PRINTED`, rendered by ``sympy.latex``), each with
  the verdict of its check against the library's own Newton-Euler derivation
  (:func:`rollingdisk.symbolic.sections34.checks_sections_3_4`): the form shown is the
  one the derivation confirms, the correction where the paper is misprinted.
"""

from __future__ import annotations

import io
from contextlib import redirect_stdout

from docutils import nodes
from sphinx.util.docutils import SphinxDirective


def _section(doc, title: str, ident: str) -> nodes.section:
    sec = nodes.section(ids=[ident])
    sec += nodes.title(text=title)
    return sec


class CLIReference(SphinxDirective):
    """Every command of ``rollingdisk`` with its ``--help``, from the parsers."""

    def run(self):
        import argparse

        from rollingdisk.cli.app import COMMANDS, build_parser

        out = []
        top = build_parser()
        para = nodes.paragraph(text="rollingdisk --help:")
        out += [para, nodes.literal_block(text=top.format_help(), language="text")]
        sub = next(a for a in top._actions if isinstance(a, argparse._SubParsersAction))
        for name, _module, text in COMMANDS:
            sec = _section(self, f"rollingdisk {name}", f"cli-{name}")
            sec += nodes.paragraph(text=text[:1].upper() + text[1:] + ".")
            help_text = sub.choices[name].format_help()
            sec += nodes.literal_block(text=help_text, language="text")
            out.append(sec)
        return out


def _latex(form) -> str:
    import sympy as sp

    if isinstance(form, tuple | list):
        return r",\quad ".join(_latex(f) for f in form)
    if isinstance(form, str):
        return r"\text{" + form.replace("_", r"\_") + "}"
    return sp.latex(form)


class Equations(SphinxDirective):
    """The printed statements of sections 3-4 as math, with the derivation's verdicts."""

    def run(self):
        from rollingdisk.symbolic.printed import PRINTED
        from rollingdisk.symbolic.sections34 import checks_sections_3_4

        with redirect_stdout(io.StringIO()):
            rows = {r.equation + (r.quantity and f" {r.quantity}"): r
                    for r in checks_sections_3_4()}
        by_label: dict = {}
        for row in rows.values():
            by_label.setdefault(row.equation, []).append(row)
        out = []
        for key, printed in PRINTED.items():
            form = printed.correct_form if printed.correct_form is not None else printed.form
            if form is None or isinstance(form, int | float):
                continue
            found = by_label.get(printed.equation, [])
            status = found[0].status if found else "unchecked"
            ident = "eq-" + "".join(ch if ch.isalnum() else "-" for ch in key).strip("-")
            sec = _section(self, f"{key}: {status}", ident)
            sec += nodes.paragraph(text=("as corrected: " + printed.correct)
                                   if printed.correct_form is not None and printed.correct
                                   else "as printed: " + printed.text)
            latex = _latex(form)
            sec += nodes.math_block(latex, latex, nowrap=False, number=None)
            out.append(sec)
        return out


def setup(app):
    app.add_directive("rollingdisk-cli", CLIReference)
    app.add_directive("rollingdisk-equations", Equations)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
