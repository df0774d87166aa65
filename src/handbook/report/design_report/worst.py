"""The design report's worst-case analysis (section 4), written against
``handbook.design.worstcase.analyse(table, result, n=100_000, seed=1) -> WorstCase``: per quantity the extreme
value (EVA), root-sum-square (RSS) and Monte Carlo bounds beside its limits and its yield, a histogram of the
Monte Carlo samples, the distributions assumed, the sensitivity ranking and the drift sentences."""
from __future__ import annotations

from ...core.units import readable
from ...design.worstcase import SEED, N  # the Monte Carlo run the report asks for: design --worstcase's too
from .page import esc, figure_svg, note, table, value
from .sections import title


def _pair(key: str, low, high, unit: str) -> str:
    if low is None and high is None:
        return "—"
    shown = lambda k, v: "—" if v is None else value(f"{key}.{k}", v, unit)  # noqa: E731
    return f"{shown('low', low)} … {shown('high', high)}"


def _share(x) -> str:
    return "—" if x is None else f"{x:.2%}".replace("%", " %")


#: below this share of a lot meeting every limit, the report warns (section 7 too)
YIELD_WARN = 0.999


def quantities_table(t: str, wc) -> str:
    """One row per quantity: nominal, EVA, RSS and Monte Carlo bounds, the limits."""
    rows = []
    for q in wc.quantities:
        key = f"wc.{t}.{q.key}"
        rows.append([esc(q.label), value(f"{key}.nominal", q.nominal, q.unit),
                     _pair(f"{key}.eva", q.eva_low, q.eva_high, q.unit), _pair(f"{key}.rss", q.rss_low, q.rss_high, q.unit),
                     _pair(f"{key}.mc", q.mc_low, q.mc_high, q.unit), _pair(f"{key}.limit", q.limit_low, q.limit_high, q.unit)])
    return table(["quantity", "nominal", "extreme value (EVA, every corner)",
                  "RSS (each side: root-sum-square of each input's move that way)",
                  "Monte Carlo (0.005 % .. 99.995 % of the lot)", "limits"], rows, (1,))


def yields_table(wc) -> str:
    """The share of the lot inside each limit, and inside all of them together."""
    rows = [[esc(name), _share(y)] for name, y in wc.yields.items()]
    rows.append(["<b>every limit above, together</b>", f"<b>{_share(wc.yield_all)}</b>"])
    return table(["limit", "share of the lot inside it"], rows, (1,))


def histogram(t: str, q, samples) -> str:
    """The Monte Carlo samples of one quantity as a histogram, with the nominal, the EVA bounds and the limits."""
    import numpy as np
    from matplotlib.figure import Figure

    from ..figures import format_axis

    scale, unit = (100.0, "%") if q.unit == "%" else (1.0, q.unit.replace("ohm", "Ω"))
    x = np.asarray(samples, dtype=float) * scale
    fig = Figure(figsize=(6.4, 2.4))
    ax = fig.add_subplot()
    ax.hist(x[np.isfinite(x)], bins=80, color="#4878a8", histtype="stepfilled")  # one path, not a bar per bin
    ax.axvline(q.nominal * scale, color="k", lw=1, label="nominal")
    for k, v in enumerate(b for b in (q.eva_low, q.eva_high) if b is not None):
        ax.axvline(v * scale, color="0.4", ls=":", lw=1, label="EVA" if k == 0 else None)
    for k, v in enumerate(b for b in (q.limit_low, q.limit_high) if b is not None):
        ax.axvline(v * scale, color="#c0392b", ls="--", lw=1.2, label="limit" if k == 0 else None)
    ax.set_xlabel(q.label[:70] + (" (%)" if unit == "%" else ""))
    ax.set_ylabel("samples")
    if unit not in ("%", "1", ""):  # a pure number takes no SI prefix ("300 m1")
        format_axis(ax, "x", unit)
    ax.legend(fontsize=7, loc="upper right")
    return figure_svg(fig, f"wc-{t}-{q.key}", f"{q.label}: {len(x):,} Monte Carlo samples")


def one(t: str, wc) -> str:
    """The worst-case analysis of one design, as HTML."""
    kinds = sorted({d.kind for d in wc.distributions})
    out = [f"<h3>{esc(title(t))}</h3>",
           f"<p>Monte Carlo: {wc.n:,} samples, seed {wc.seed}, every part {' or '.join(kinds) or 'as stated'} inside "
           f"the range the table <i>Distributions assumed</i> below gives it (with its source); every limit the next table "
           f"lists met together in {_share(wc.yield_all)} of them.</p>"]
    if wc.yield_all < YIELD_WARN:
        out.append(f'<p class="warn"><b>Below {_share(YIELD_WARN)}:</b> at these distributions '
                   f"{_share(1 - wc.yield_all)} of the boards miss a limit (which, below); the design's corners do "
                   "not cover every spread this analysis draws.</p>")
    out += [yields_table(wc), quantities_table(t, wc),
            "<p>RSS takes each input's full move to its end, root-sum-squared: with uniform inputs that is √3 ≈ 1.73 "
            "standard deviations of the sum, so where several inputs share the spread (a near-normal sum) about 4 % "
            "of boards lie beyond each RSS bound. It is a statistical estimate, not a worst case; EVA is.</p>"]
    out += [histogram(t, q, wc.samples[q.key]) for q in wc.quantities if q.key in wc.samples]
    out.append("<h4>Distributions assumed</h4>")
    out.append(table(["part", "distribution", "low", "high", "source"],
                     [[esc(d.part), esc(d.kind), value(f"wc.{t}.dist.{d.part}.low", d.low, d.unit or "1"),
                       value(f"wc.{t}.dist.{d.part}.high", d.high, d.unit or "1"), esc(readable(d.cite))]
                      for d in wc.distributions],
                     (2, 3)))
    binding = getattr(wc, "binding", "")
    binding = next((q.label for q in wc.quantities if q.key == binding), binding)  # as the tables above name it
    out.append("<h4>Sensitivity: what the spread comes from</h4>" + (
        f"<p>Ranked for the quantity with the least worst-case margin: <b>{esc(binding)}</b> (another quantity "
        "can rank its sources differently).</p>" if binding else ""))
    out.append(table(["source", "share of the spread", "worst margin if its spread were halved", "yield if halved"],
                     [[esc(s.source), _share(s.share), _share(s.margin_if_halved), _share(s.yield_if_halved)]
                      for s in wc.sensitivity], (1, 2, 3)))
    if wc.by_limit:
        label = {q.key: q.label for q in wc.quantities}
        out.append("<p>Every limit, least worst-case margin first, with the tolerance that moves it most (its share "
                   "of that quantity's first-order spread):</p>")
        out.append(table(["quantity", "worst-case margin", "moved most by", "its share"],
                         [[esc(label.get(x.key, x.key)), _share(x.margin), esc(x.source or "none"), _share(x.share)]
                          for x in wc.by_limit], (1, 3)))
    if wc.drift:
        out.append("<h4>Drift</h4><ul>" + "".join(f"<li>{esc(readable(s))}</li>" for s in wc.drift) + "</ul>")
    return "".join(out)


#: the fresh lot a design chosen for yield is re-checked on: another seed, ten times the search's boards
RECHECK_SEED, RECHECK_FACTOR = 2, 10


def yield_recheck(ctx, t: str, result) -> str:
    """A limiter chosen with ``criterion = "yield"``: the lot that accepted it beside a fresh one (another seed,
    ten times the boards), each judged as the search judged it (the window narrowed by ``min_margin``, the
    op-amp's input headroom, a 3-sigma bound on the failure rate against ``yield_min``); a fresh lot that misses is
    a warning (section 7). Empty for any other design."""
    if t != "current_limiter" or getattr(result, "mc_yield", None) is None:
        return ""
    from ...design.limiter import by_yield

    s, network = result.spec, (result.r9, result.r10, result.r11, result.r12, result.r13)
    n = by_yield.N * RECHECK_FACTOR
    fresh = by_yield.lot_yield(result.r7, network, s, n=n, seed=RECHECK_SEED)
    ok = by_yield.meets(fresh, n, s["yield_min"])
    if not ok:
        ctx.spice_warnings.append((t, f"chosen for yield, but a fresh lot of {n:,} boards (seed {RECHECK_SEED}) "
                                      f"keeps {_share(fresh)}: its 3-sigma bound misses yield_min = "
                                      f"{_share(s['yield_min'])}"))
    rows = [[f"the search's lot (seed {by_yield.SEED})", f"{by_yield.N:,}", _share(result.mc_yield), "yes"],
            [f"a fresh lot (seed {RECHECK_SEED})", f"{n:,}", _share(fresh), "yes" if ok else "<b>no</b>"]]
    return ("<h4>Chosen for yield: re-checked on a fresh lot</h4><p>The design was accepted on the search's own lot "
            "(the window narrowed by min_margin at both ends of the temperature span, the op-amp's input headroom; "
            f"a 3-sigma upper bound of the failure rate at most 1 − yield_min = {_share(1 - s['yield_min'])}). "
            "The same judgement on a lot it was not chosen on, ten times larger:</p>"
            + table(["lot", "boards", "yield", "3-sigma bound meets yield_min"], rows, (1, 2)))


def section(ctx, analyse=None) -> str:
    """Section 4: each designed table's worst-case analysis.

    Parameters
    ----------
    ctx : Context
        The report's context (the designed tables).
    analyse : callable, optional
        ``analyse(table, result, n=, seed=)``; default ``handbook.design.worstcase.analyse`` (tests pass a
        stand-in).

    Returns
    -------
    str
        The section's HTML.
    """
    if analyse is None:
        from ...design.worstcase import analyse
    out = []
    for t, result in ctx.designed.items():
        try:
            wc = analyse(t, result, n=N, seed=SEED)
        except Exception as exc:  # another module's failure is reported in its place and among the warnings
            out.append(f"<h3>{esc(title(t))}</h3>" + note(f"worst-case analysis failed: {type(exc).__name__}: {exc}"))
            ctx.spice_warnings.append((t, f"worst-case analysis failed: {type(exc).__name__}: {exc}"))
            continue
        if wc.yield_all < YIELD_WARN:
            ctx.spice_warnings.append((t, f"worst case: every limit met by {_share(wc.yield_all)} of a Monte Carlo "
                                          f"lot ({', '.join(f'{k} {_share(v)}' for k, v in wc.yields.items())}) at "
                                          "the distributions section 4 states"))
        out.append(one(t, wc) + yield_recheck(ctx, t, result))
    return "".join(out)
