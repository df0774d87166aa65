"""LaTeX to presentation MathML, for the subset the calculation sheet writes (offline: no MathJax, no network).

The sheet's LaTeX comes from :func:`sympy.latex` and the registries' ``printed_tex``: fractions, roots,
sub- and superscripts, ``\\left( \\right)``, ``\\cdot``, thin spaces, ``\\text``/``\\mathrm`` and Greek letters.
:func:`to_mathml` turns that into a ``<math>`` element Chromium renders natively; a command it does not know
is shown as its name (never dropped), so nothing of an equation is lost silently.
"""
from __future__ import annotations

import re
from html import escape

_GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "epsilon": "ϵ", "varepsilon": "ε", "zeta": "ζ",
          "eta": "η", "theta": "θ", "lambda": "λ", "mu": "μ", "nu": "ν", "pi": "π", "rho": "ρ", "sigma": "σ",
          "tau": "τ", "phi": "ϕ", "varphi": "φ", "omega": "ω", "Delta": "Δ", "Gamma": "Γ", "Theta": "Θ",
          "Lambda": "Λ", "Sigma": "Σ", "Phi": "Φ", "Omega": "Ω", "Psi": "Ψ", "ell": "ℓ"}
_OPERATORS = {"cdot": "·", "times": "×", "ge": "≥", "geq": "≥", "le": "≤", "leq": "≤", "approx": "≈",
              "pm": "±", "infty": "∞", "checkmark": "✓", "%": "%", "{": "{", "}": "}", "ldots": "…"}
_MINUS = "\N{MINUS SIGN}"
_SPACES = {",": "0.1667em", ";": "0.2778em", ":": "0.2222em", "quad": "1em", "qquad": "2em", " ": "0.25em",
           "!": "0em"}
_TOKEN = re.compile(r"\\(?:text|mathrm|operatorname|textrm|mbox)\{([^{}]*)\}|\\([A-Za-z]+|.)|(\d+(?:\.\d+)?)|(\s+)|([A-Za-z]+|.)",
                    re.S)


def _tokens(tex: str) -> list[tuple[str, str]]:
    out = []
    for m in _TOKEN.finditer(tex):
        text, cmd, num, space, char = m.groups()
        if text is not None:
            out.append(("text", text))
        elif cmd:
            out.append(("cmd", cmd))
        elif num:
            out.append(("num", num))
        elif space:
            continue
        else:
            out.append(("char", char))
    return out


class _Parser:
    def __init__(self, tex: str):
        self.toks = _tokens(tex)
        self.i = 0

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else (None, None)

    def take(self):
        tok = self.peek()
        self.i += 1
        return tok

    def row(self, stop: str | None = None) -> str:
        """Atoms up to ``stop`` (a closing brace, or a ``\\right``) or the end, as one ``<mrow>``."""
        parts = []
        while self.i < len(self.toks):
            kind, val = self.peek()
            if (kind, val) == ("char", stop) or (kind, val) == ("cmd", "right"):
                break
            parts.append(self.scripted())
        return "<mrow>" + "".join(parts) + "</mrow>"

    def group(self) -> str:
        """A braced group, or the next single atom."""
        if self.peek() == ("char", "{"):
            self.take()
            inner = self.row("}")
            self.take()
            return inner
        return self.atom()

    def scripted(self) -> str:
        base = self.atom()
        sub = sup = None
        while self.peek() in (("char", "_"), ("char", "^")):
            mark = self.take()[1]
            arg = self.group()
            sub, sup = (arg, sup) if mark == "_" else (sub, arg)
        if sub is not None and sup is not None:
            return f"<msubsup>{base}{sub}{sup}</msubsup>"
        if sub is not None:
            return f"<msub>{base}{sub}</msub>"
        if sup is not None:
            return f"<msup>{base}{sup}</msup>"
        return base

    def atom(self) -> str:  # noqa: C901 - one branch per kind of token
        kind, val = self.take()
        if kind == "num":
            return f"<mn>{val}</mn>"
        if kind == "text":
            text = val.replace("\\Omega", "Ω").replace("\\mu", "µ").replace("\\,", "\u2009").replace("\\", "")
            return f"<mtext>{escape(text)}</mtext>"
        if kind == "char":
            if val == "{":
                inner = self.row("}")
                self.take()
                return inner
            if val.isalpha():
                return f"<mi>{escape(val)}</mi>"
            return f"<mo>{escape(_MINUS if val == '-' else val)}</mo>"
        if val in ("frac", "dfrac", "tfrac"):
            return f"<mfrac>{self.group()}{self.group()}</mfrac>"
        if val == "sqrt":
            return f"<msqrt>{self.group()}</msqrt>"
        if val == "left":
            opening = self.take()[1]
            inner = self.row()
            self.take()  # \right
            closing = self.take()[1]
            return (f"<mrow><mo>{escape(opening if opening != '.' else '')}</mo>{inner}"
                    f"<mo>{escape(closing if closing != '.' else '')}</mo></mrow>")
        if val in ("mathit", "mathbf", "boldsymbol"):
            return self.group()
        if val == "mathcal":  # a reluctance's script R
            return self.group().replace("<mi>", '<mi mathvariant="script">')
        if val in _SPACES:
            return f'<mspace width="{_SPACES[val]}"/>'
        if val == "mu" and self.peek()[0] == "text":  # a unit's prefix: the micro sign
            return '<mi mathvariant="normal">µ</mi>'
        if val in _GREEK:
            variant = ' mathvariant="normal"' if val[0].isupper() else ""
            return f"<mi{variant}>{_GREEK[val]}</mi>"
        if val in _OPERATORS:
            return f"<mo>{escape(_OPERATORS[val])}</mo>"
        return f"<mi>{escape(val)}</mi>"  # unknown command: its name, not dropped


def to_mathml(tex: str, display: bool = True) -> str:
    """The LaTeX ``tex`` as a presentation-MathML ``<math>`` element.

    Parameters
    ----------
    tex : str
        LaTeX of the subset :mod:`sympy` and the registries write (fractions, roots, scripts, ``\\left``/``\\right``,
        ``\\text``, Greek letters, ``\\cdot``, thin spaces).
    display : bool
        True: ``display="block"``; False: inline.

    Returns
    -------
    str
        ``<math xmlns="http://www.w3.org/1998/Math/MathML" ...>...</math>``, well-formed XML.
    """
    parser = _Parser(tex)
    body = parser.row()
    while parser.i < len(parser.toks):  # a stray closing brace or \right: skip it and go on
        parser.take()
        body += parser.row()
    mode = "block" if display else "inline"
    return f'<math xmlns="http://www.w3.org/1998/Math/MathML" display="{mode}">{body}</math>'
