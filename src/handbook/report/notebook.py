"""What every chapter's first cells call: one setup, glued values, equations shown as typeset math."""
from __future__ import annotations

import warnings

import matplotlib
import numpy as np
from IPython.display import Markdown, Math, display


def setup() -> None:
    """The one setup call of every chapter: parameters a reader injected are checked (an unknown name or a value
    of the wrong kind stops the chapter here, naming it), then quiet warnings and deterministic plots."""
    from IPython import get_ipython

    from ..core import parameters

    shell = get_ipython()
    if shell is not None:
        parameters.check_history(list(shell.user_ns.get("In", [])))
    warnings.filterwarnings("ignore", category=DeprecationWarning)
    warnings.filterwarnings("ignore", category=FutureWarning)
    # matplotlib warns when its search for the "best" legend spot takes over 1 s: a statement about the
    # machine's load, not the plot, which would make a cell's output depend on what else is running
    warnings.filterwarnings("ignore", message="Creating legend with loc=\"best\" can be slow")
    np.set_printoptions(precision=4, suppress=True)
    matplotlib.rcParams.update({
        "figure.figsize": (7.0, 3.8), "figure.dpi": 100, "axes.grid": True, "grid.alpha": 0.3,
        "svg.hashsalt": "handbook", "axes.spines.top": False, "axes.spines.right": False,
    })


def show_equation(eq) -> None:
    """Printed form, derived form, and the verdict of the symbolic check (units as a person reads them)."""
    from .tables import readable

    s = eq.summary()
    s["note"] = readable(s["note"])
    display(Markdown(readable(f"**{eq.title}** ({eq.source})  \nprinted:")))
    display(Math(s["printed_latex"]))
    if s.get("empirical"):
        # no circuit law: the datasheet does not show the circuit; the check is against its own figures
        display(Markdown(f"**empirical**, not derived (fitted to {s['fitted_to']}); the printed form at the "
                         "datasheet's own figures:"))
        display(Math(s["derived_latex"]))
        dims = "dimensions consistent" if s["dimensions_ok"] else "**dimension error**"
        verdict = "reproduces every figure" if s["agrees"] else "**misses figures the datasheet prints**"
        display(Markdown(f"*Check:* {verdict}; {dims}. {s['note']}"))
        return
    display(Markdown(readable(f"derived ({eq.law}):")))
    display(Math(s["derived_latex"]))
    dims = "dimensions consistent" if s["dimensions_ok"] else "**dimension error**"
    verdict = "agrees" if s["agrees"] else "agrees (constant rounded)" if s["rounded_constants"] else "**differs**"
    display(Markdown(f"*Check:* {verdict}; {dims}. {s['note']}"))


def glue_all(**values) -> None:
    """Glue numbers for the prose (myst-nb), as plain Python floats so their repr is stable; texts with their units
    as a person reads them."""
    from myst_nb import glue

    from .tables import readable

    for name, v in values.items():
        v = readable(v) if isinstance(v, str) else v
        glue(name, float(v) if isinstance(v, (int, float, np.floating, np.integer)) else v, display=False)


def is_note(chosen: dict, defaults: dict, rel: float = 1e-9) -> bool:
    """True when every parameter in ``chosen`` equals the chapter's default (the note's value).

    A chapter's prose that is true only for the note's board (``the note's choice``, ``the board's 18 nF``)
    is glued through :func:`note_only`, which shows it only when this is true.
    """
    for key, value in chosen.items():
        if key not in defaults:  # a derived entry, not an input
            continue
        ref = defaults[key]
        if isinstance(value, (int, float)) and isinstance(ref, (int, float)) and not isinstance(value, bool):
            if abs(float(value) - float(ref)) > rel * max(abs(float(ref)), 1e-300):
                return False
        elif value != ref:
            return False
    return True


def note_only(name: str, text: str, note: bool, otherwise: str = "") -> None:
    """Glue a Markdown sentence that holds only for the note's inputs, under ``name`` (``{glue:md}`name```).

    With the note's inputs the sentence is shown as written; with a reader's inputs ``otherwise`` is shown
    instead (by default nothing), so a re-run never states the note's result as the reader's.
    """
    sentence(name, text if note else otherwise)


def sentence(name: str, text: str) -> None:
    """Glue a Markdown sentence built from this run's values under ``name`` (``{glue:md}`name```): prose whose
    wording, not only its numbers, depends on the reader's inputs."""
    from myst_nb import glue

    from .tables import readable

    glue(name, Markdown(readable(text)), display=False)
