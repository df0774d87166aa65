"""What the drawing tests share: a schematic rendered to matplotlib, then read back as an engineer reads it.

* every text (designator, value, net name, sign) as the figure draws it, with its extent in pixels;
* every part's body: the symbol without its leads, in the drawing's units;
* every stroke of ink: wires, leads and symbols, as line segments in pixels;
* the nets: which wires and pins touch.

:func:`faults` lists what an engineer would reject: two texts on each other, a text on a stroke of ink, two
part bodies on each other, a sign drawn as strokes that turn with the symbol. Independent of the drawing code:
it sees only what schemdraw placed and what matplotlib rendered.
"""
from __future__ import annotations

import math
import re

import numpy as np

#: schemdraw elements that are wiring or annotation, not a part's body
WIRING = {"Line", "Wire", "Dot", "Label", "Ground", "Vdd", "Vss", "Gap", "Arrow", "Tag", "DotDotDot"}
PX = 1.0  # pixels two extents may share before they count as overlapping (antialiasing, rounding)
BODY_TOL = 0.05  # drawing units two bodies may share (parts that touch at a pin)
CLEAR = 0.3  # drawing units a wire not connected to a part keeps from its body
#: the pins of a part that must each meet a wire, by symbol (two-terminal parts: start and end)
PINS = {"Opamp": ("in1", "in2", "out", "vd", "vs"), "BjtPnp": ("base", "collector", "emitter"),
        "BjtNpn": ("base", "collector", "emitter")}


def plain(text: str) -> str:
    """A label as read: mathtext undone ("$V_\\mathrm{LOW}$ 875 mV" -> "V_LOW 875 mV")."""
    text = re.sub(r"\\mathrm\{([^}]*)\}", r"\1", str(text))
    text = re.sub(r"_\{([^}]*)\}", r"_\1", text)
    return text.replace("$", "").replace("{", "").replace("}", "")


def render(drawing):
    """(matplotlib axes, renderer) of the drawing, drawn as saved: at its own size (half an inch a unit)."""
    import matplotlib.pyplot as plt

    fig = drawing.draw(show=False).getfig()
    fig.subplots_adjust(0, 0, 1, 1)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    plt.close(fig)  # the artists and their extents stay readable
    return fig.axes[0], renderer


def texts(ax, renderer) -> list[tuple[str, tuple[float, float, float, float], object]]:
    """[(text as written, (x0, y0, x1, y1) in pixels, the Text artist)] of every non-empty text."""
    out = []
    for t in ax.texts:
        if t.get_text().strip() and t.get_visible():
            e = t.get_window_extent(renderer)
            out.append((t.get_text(), (e.x0, e.y0, e.x1, e.y1), t))
    return out


def _polylines(element):
    """The element's strokes in drawing units: lists of points (gaps split a path), and circles as boxes."""
    from schemdraw.segments import Segment, SegmentText

    for seg in element.segments:
        if isinstance(seg, SegmentText):
            continue
        seg = seg.xform(element.transform)
        if isinstance(seg, Segment):
            run = []
            for p in seg.path:
                if p is None or any(math.isnan(c) for c in p):
                    if len(run) > 1:
                        yield run
                    run = []
                else:
                    run.append((float(p[0]), float(p[1])))
            if len(run) > 1:
                yield run
        else:  # a circle, arc or polygon: its box's outline
            x0, y0, x1, y1 = seg.get_bbox()
            yield [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]


def body(element) -> tuple[float, float, float, float] | None:
    """The part's symbol without its leads (drawing units), or None for wiring."""
    from schemdraw.elements import Element2Term
    from schemdraw.elements.opamp import Opamp
    from schemdraw.segments import SegmentText

    name = type(element).__name__
    if name in WIRING:
        return None
    segs = [s for s in element.segments if not isinstance(s, SegmentText)]
    if isinstance(element, Opamp):
        segs = segs[:1]  # the triangle; its leads and signs are not its body
    boxes = []
    for k, seg in enumerate(segs):
        seg = seg.xform(element.transform)
        if k == 0 and isinstance(element, Element2Term) and len(getattr(seg, "path", ())) > 2:
            pts = [p for p in seg.path[1:-1] if not any(math.isnan(c) for c in p)]  # without the two leads
            if pts:
                xs, ys = zip(*pts)
                boxes.append((min(xs), min(ys), max(xs), max(ys)))
            continue
        boxes.append(tuple(seg.get_bbox()))
    if not boxes:
        return None
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))


def _box(points) -> tuple[float, float, float, float]:
    xs, ys = zip(*points)
    return min(xs), min(ys), max(xs), max(ys)


def _overlap(a, b, tol: float) -> bool:
    return min(a[2], b[2]) - max(a[0], b[0]) > tol and min(a[3], b[3]) - max(a[1], b[1]) > tol


def _crosses(p, q, box) -> bool:
    """Whether the segment p-q enters the box (x0, y0, x1, y1) (Liang-Barsky clipping)."""
    (x0, y0, x1, y1), dx, dy = box, q[0] - p[0], q[1] - p[1]
    t0, t1 = 0.0, 1.0
    for pk, qk in ((-dx, p[0] - x0), (dx, x1 - p[0]), (-dy, p[1] - y0), (dy, y1 - p[1])):
        if pk == 0:
            if qk < 0:
                return False
        else:
            t = qk / pk
            if pk < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 > t1:
                return False
    return True


def _shrink(box, by: float):
    return (box[0] + by, box[1] + by, box[2] - by, box[3] - by)


def _name(element) -> str:
    labels = [plain(lab.label) for lab in getattr(element, "_userlabels", [])]
    return f"{type(element).__name__}" + (f" '{labels[0]}'" if labels else "")


def faults(drawing, rendered=None) -> list[str]:
    """What an engineer would reject in the rendered drawing, one line each (empty: none). ``rendered``: the
    (axes, renderer) of :func:`render`, if already drawn."""
    ax, renderer = rendered or render(drawing)
    to_px = ax.transData.transform
    found = []
    tx = texts(ax, renderer)
    for i, (a, box_a, _) in enumerate(tx):
        for b, box_b, _ in tx[i + 1:]:
            if _overlap(box_a, box_b, PX):
                found.append(f"text {plain(a)!r} overlaps text {plain(b)!r}")
    strokes = []  # (pixel points, their box, owner)
    for el in drawing.elements:
        for line in _polylines(el):
            pts = [tuple(to_px(p)) for p in line]
            strokes.append((pts, _box(pts), el))
    for text, box, _ in tx:
        inner = _shrink(box, PX)
        hit = {_name(el) for pts, around, el in strokes
               if _overlap(around, inner, -1e-9) and any(_crosses(p, q, inner) for p, q in zip(pts, pts[1:]))}
        found += [f"text {plain(text)!r} lies on {who}" for who in sorted(hit)]
    bodies = [(body(el), el) for el in drawing.elements]
    bodies = [(b, el) for b, el in bodies if b is not None]
    for i, (a, ea) in enumerate(bodies):
        for b, eb in bodies[i + 1:]:
            if _overlap(a, b, BODY_TOL):
                found.append(f"{_name(ea)} overlaps {_name(eb)}")
    found += _crowded(drawing, bodies)
    found += [f"{_name(el)}: pin {pin} meets no wire" for el, pin in dangling(drawing)]
    return found


def _pins(element) -> dict[str, tuple[float, float]]:
    from schemdraw.elements import Element2Term

    names = PINS.get(type(element).__name__, ("start", "end") if isinstance(element, Element2Term) else ())
    return {n: tuple(map(float, element.absanchors[n])) for n in names}


def _near(p, q, tol: float = 1e-3) -> bool:
    return abs(p[0] - q[0]) < tol and abs(p[1] - q[1]) < tol


def _on(point, line, tol: float = 1e-3) -> bool:
    """Whether ``point`` lies on the polyline (drawing units)."""
    for a, b in zip(line, line[1:]):
        ab, ap = np.subtract(b, a), np.subtract(point, a)
        length = float(np.dot(ab, ab))
        t = 0.0 if length == 0 else min(max(float(np.dot(ap, ab)) / length, 0.0), 1.0)
        if np.hypot(*(ap - t * ab)) < tol:
            return True
    return False


def _crowded(drawing, bodies) -> list[str]:
    """A wire that runs through, or within CLEAR of, a part's body it is not connected to."""
    out = []
    lines = [(other, line, _box(line)) for other in drawing.elements for line in _polylines(other)]
    for box, el in bodies:
        grown, pins = _shrink(box, -CLEAR), list(_pins(el).values()) + [tuple(map(float, p)) for p in el.absanchors.values()]
        for other in drawing.elements:
            if other is el:
                continue
            for line in (line for o, line, around in lines if o is other and _overlap(around, grown, -1e-9)):
                if any(_near(line[0], p) or _near(line[-1], p) for p in pins):
                    continue  # wired to this part
                if any(_crosses(a, b, grown) for a, b in zip(line, line[1:])):
                    out.append(f"{_name(other)} runs into {_name(el)}")
                    break
    return out


def dangling(drawing) -> list[tuple[object, str]]:
    """[(part, pin)] of every pin of a part that no other element's stroke or dot meets."""
    lines = [(el, line) for el in drawing.elements for line in _polylines(el)]
    dots = [(el, tuple(map(float, el.absanchors["center"]))) for el in drawing.elements if type(el).__name__ == "Dot"]
    out = []
    for el in drawing.elements:
        if type(el).__name__ in WIRING:
            continue
        for pin, at in _pins(el).items():
            if not (any(o is not el and _on(at, line) for o, line in lines) or any(_near(at, c) for _, c in dots)):
                out.append((el, pin))
    return out


#: text an engineer would not accept: ASCII units, and names with their subscripts as raw text
ASCII_UNITS = re.compile(r"\d\s*[kMmµu]?ohms?\b|\bohm\b|\d\s*u[FAHVWs]\b|\bkohm\b", re.IGNORECASE)
RAW_SUBSCRIPT = re.compile(r"\b[A-Za-z]+_[A-Za-z0-9(]|\b[VI]\d+\([A-Z]\)")


def style_faults(strings) -> list[str]:
    """Texts with ASCII units ("680 ohm", "10 uF") or a raw subscript ("V_CE(sat)", "V12(H)") outside mathtext."""
    out = []
    for text in strings:
        outside = re.sub(r"\$[^$]*\$", " ", str(text))  # mathtext is typeset: only the rest is read as raw
        if ASCII_UNITS.search(outside):
            out.append(f"{text!r}: units in ASCII")
        if RAW_SUBSCRIPT.search(outside):
            out.append(f"{text!r}: a subscript as raw text")
    return out


def net(drawing, point) -> set[tuple[str, str]]:
    """{(part's first label, pin)} of every part pin on the same net as ``point``: the wires (Line, Dot)
    that touch it, and the wires that touch those, followed to the end."""
    wires = [line for el in drawing.elements if type(el).__name__ in ("Line", "Wire") for line in _polylines(el)]
    reached, frontier, seen = [tuple(map(float, point))], [tuple(map(float, point))], set()
    while frontier:
        p = frontier.pop()
        for k, line in enumerate(wires):
            if k not in seen and (_on(p, line) or any(_on(q, [p, p]) for q in line)):
                seen.add(k)
                frontier += [line[0], line[-1]]
                reached += [line[0], line[-1]]
    lines = [wires[k] for k in seen] or [[tuple(map(float, point))] * 2]
    out = set()
    for el in drawing.elements:
        if type(el).__name__ in WIRING:
            continue
        name = plain(el._userlabels[0].label).split()[0] if getattr(el, "_userlabels", None) else type(el).__name__
        for pin, at in _pins(el).items():
            if any(_on(at, line) for line in lines):
                out.add((name, pin))
    return out


def amplifier_signs(drawing, rendered=None) -> list[dict]:
    """For every op-amp symbol: whether schemdraw drew its own signs (strokes that turn with it), and the
    upright "+" and "−" texts nearest its two inputs: [{"strokes": bool, "in1": sign or None, "in2": ...,
    "element": the Opamp}]."""
    from schemdraw.elements.opamp import Opamp

    ax, renderer = rendered or render(drawing)
    to_data = ax.transData.inverted().transform
    signs = [(t, to_data(((box[0] + box[2]) / 2, (box[1] + box[3]) / 2))) for t, box, artist in texts(ax, renderer)
             if t.strip() in ("+", "−", "-") and artist.get_rotation() == 0]
    out = []
    for el in drawing.elements:
        if not isinstance(el, Opamp):
            continue
        row = {"strokes": bool(el.params.get("sign", True)), "element": el}
        for pin in ("in1", "in2"):
            at = np.asarray(getattr(el, pin), dtype=float)
            near = [(float(np.hypot(*(at - centre))), t.strip()) for t, centre in signs]
            near = [n for n in near if n[0] < 1.5]  # inside the symbol, by its pin (drawing units)
            row[pin] = min(near)[1] if near else None
        out.append(row)
    return out
