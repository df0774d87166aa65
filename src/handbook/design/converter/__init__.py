"""The TCA5600 dc/dc converter by eq 1 to 6a, down to a real coil.

* :mod:`.operating`: the operating point at the corners of R1, A_L and the TCA5600's figures (R1 from its series,
  L1 as a maximum, the frequency range, f_min raised out of the audio band);
* :mod:`.result`: the spec checked, the choice of the coil, the result and its warnings;
* :mod:`.coil`: a coil wound on one core of the database (turns, gap, wire, flux, losses, temperature rise);
* :mod:`.cores`: the candidate cores, materials and wires, read from PyOpenMagnetics' database.
"""
from ..common import explained
from .coil import frequency, supplies
from .operating import AUDIO_BAND, corner, designed_at, r1_drift, r1_ends, source_params
from .result import ConverterResult, checked, choose, design, sweep

TABLE = "converter"
#: the tolerances and spread the converter's corners take, each zeroed in turn by :func:`sensitivity`
TOLERANCES = ("r1_tolerance", "r1_tempco", "a_l_tolerance", "device_spread")


def enumerate(spec: dict | None = None) -> dict | None:
    """Exhaustive: every candidate core of the database wound for ``spec``, and the smallest that meets every
    limit, keyed as :class:`ConverterResult` reports it (:func:`choose` gives every candidate).

    Parameters
    ----------
    spec : dict or None
        The ``[converter]`` table, {key: value} in SI units (temperatures in C); missing keys take their
        defaults, None takes them all.

    Returns
    -------
    dict or None
        {"core_shape", "core_material", "turns", "wire"} of the smallest candidate (by effective volume) that
        meets every limit, or None when none does.

    Raises
    ------
    InputError
        When ``spec`` is invalid.
    """
    _, _, coil = choose(designed_at(checked(spec)))
    return None if coil is None else {"core_shape": coil.shape, "core_material": coil.material, "turns": coil.turns,
                                      "wire": coil.wire}


def explain(spec: dict | None = None):
    """Why ``spec`` cannot be met, and what can (an :class:`~handbook.design.solvers.Infeasible`), or None.

    Parameters
    ----------
    spec : dict or None
        The ``[converter]`` table, {key: value} in SI units (temperatures in C); missing keys take their
        defaults, None takes them all.

    Returns
    -------
    Infeasible or None
        The exception :func:`design` raises (its message, and ``achievable``: a lower ``i_out`` (A) or a higher
        ``f_min`` (Hz) that works, the largest core and why it fails), not raised; None when the spec can be met.

    Raises
    ------
    InputError
        When ``spec`` itself is invalid.
    """
    return explained(design, spec)


def sensitivity(result: ConverterResult) -> list[dict]:
    """What each tolerance costs: the design repeated with it at zero, one row per tolerance:
    {"source", "core" (the chosen core then), "ve" (its volume, m^3), "ve_saved" (fraction of the volume saved)}.

    Parameters
    ----------
    result : ConverterResult
        A design (:func:`design`): its checked spec is designed again with each of :data:`TOLERANCES` at zero.

    Returns
    -------
    list of dict
        One row per tolerance of :data:`TOLERANCES`: ``source`` (the key, str), ``core`` (shape and material,
        str), ``ve`` (the core's effective volume, m^3) and ``ve_saved`` (a fraction of ``result``'s core volume).

    Raises
    ------
    Infeasible
        When the spec with a tolerance at zero cannot be met (it can, whenever ``result``'s could).
    """
    rows = []
    for key in TOLERANCES:
        tight = design({**result.spec, key: 0.0})
        rows.append({"source": key, "core": f"{tight.core_shape} {tight.core_material}", "ve": tight.coil.ve,
                     "ve_saved": 1 - tight.coil.ve / result.coil.ve})
    return rows


__all__ = ["AUDIO_BAND", "TABLE", "TOLERANCES", "ConverterResult", "checked", "corner", "design", "enumerate", "explain",
           "frequency", "r1_drift", "r1_ends", "sensitivity", "source_params", "supplies", "sweep"]
