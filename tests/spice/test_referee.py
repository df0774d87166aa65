"""SPICE as a referee that can fail (handbook.spice.referee): every check holds at 20 operating points drawn from
its chapter's assumptions, and every deliberate fault in an equation is seen by an independent check of its
circuit. Together under a minute on the 2-core machine (about 25 s of ngspice)."""
import math

import pytest

from handbook.spice import checks, referee
from handbook.spice.circuit import evaluate, judge

POINTS = 20


def _name(build):
    return f"{build.__module__.split('.')[-1]}.{build.__name__}"


@pytest.mark.parametrize("build", list(referee.SPACES), ids=_name)
def test_every_check_holds_at_twenty_operating_points(ngspice, build):
    """A tolerance fitted to one operating point fails here: each check, its expected difference computed
    from physics at each point, must fall inside its numerical tolerance at all of them."""
    bad = []
    for p in referee.draw(build, POINTS):
        for r in evaluate(build(p)):
            if not r["agrees"]:
                bad.append((r["id"], f"residual {r['residual']:+.4%} against ±{r['rtol']:.3%}", p))
    assert not bad, bad[:3]


#: the builders outside the limiter decks (src/handbook/spice/limiter)
NON_LIMITER = [b for b in referee.SPACES if ".limiter" not in b.__module__]


@pytest.mark.parametrize("build", NON_LIMITER, ids=_name)
def test_every_check_holds_at_the_two_extreme_corners_of_its_space(ngspice, build):
    """Beside the twenty drawn points, the space's two extreme corners: every parameter at its low end, then every
    one at its high end (the largest coils and capacitor at the highest switching frequency are where a step that
    misses the edges showed; about 6 s for every circuit)."""
    bad = []
    for end in (0, 1):
        p = {k: v[end] for k, v in referee.SPACES[build].items()}
        bad += [(r["id"], f"residual {r['residual']:+.4%} against ±{r['rtol']:.4%}", p)
                for r in evaluate(build(p)) if not r["agrees"]]
    assert not bad, bad[:3]


def test_the_spaces_hold_their_stated_reasons():
    """Each narrowed space keeps the chapter's assumption it states: CAP-CD's swing at the lowest speed with the
    largest current fits the narrowest window at the smallest capacitor drawn (eq 6), the speed loop's OTA sinks less
    than its 40 mA at the top of the control range at every corner, and the AC rows' bounds take the largest Q of
    their spaces."""
    import itertools

    from handbook.sources import an94002
    from handbook.spice import class_d, decoupling, speed, timers

    cd = referee.SPACES[timers.commutation_delay]
    swing = an94002.excursion(cd["cap_cd"][0], cd["rpm_min"][0], an94002.params()["pole_pairs"], cd["i_ch"][1])
    assert swing <= (timers.CD_HIGH[0] - timers.CD_LOW[2]) * (1 + 1e-12)
    sp = referee.SPACES[speed.circuit]
    for corner in itertools.product(*sp.values()):
        q = speed.with_defaults(speed.defaults(), dict(zip(sp, corner)))
        top = an94002.v_mot_max(q["v_supply"], q["supply_tolerance"], q["v_drop_min"])
        assert speed.i_sink(top, q) < q["i_sink"], corner
    f = referee.SPACES[class_d.circuit]
    q_max = max(r * math.sqrt(c / (2 * lo)) for lo, c, r in itertools.product(f["l_out"], f["c_out"], f["r_load"]))
    assert class_d.Q_MAX == pytest.approx(q_max)
    d = referee.SPACES[decoupling.circuit]
    assert decoupling.Q_MAX == pytest.approx(max(math.sqrt(lo / c) / r for lo, c, r in itertools.product(
        d["esl"], d["c2"], d["esr"])))


def test_the_points_cover_their_ranges():
    """Twenty seeded points reach both ends of every range, each within a twentieth of it (not twenty copies of
    one corner)."""
    for build, space in referee.SPACES.items():
        pts = referee.draw(build, POINTS)
        for key, (lo, hi) in space.items():
            got = [p[key] for p in pts]
            assert min(got) < lo + (hi - lo) / POINTS and max(got) > hi - (hi - lo) / POINTS, (_name(build), key)


@pytest.fixture(scope="module")
def refereed(ngspice):
    return {b: referee.refereed(b()) for b in checks.BUILDERS}


def test_every_fault_is_seen_by_an_independent_check_of_its_circuit(refereed):
    """The mutation test: each fault in :data:`referee.FAULTS` (a sign flipped, a term dropped, a factor 2, eq
    14 for eq 13) is seen by at least one independent row of its circuit. A circuit whose checks are all
    sanity checks (the timers) must see them with those, and says so (the chapters call them by construction)."""
    unseen = []
    for rows in refereed.values():
        cid = rows[0]["circuit"]
        independent = any(r["kind"] == "independent" for r in rows)
        for fault in referee.FAULTS[cid]:
            by = [r["id"] for r in rows if fault.label in r["faults_seen"]
                  and (r["kind"] == "independent" or not independent)]
            if not by:
                unseen.append((cid, fault.label))
    assert not unseen


def test_every_circuit_has_faults_and_each_fault_reaches_its_equation():
    """A fault whose patch reaches nothing (a function called through another name) would be 'seen' by no
    row and prove nothing: each must change at least one check's equation column (a check it removes or a build
    it breaks does not count)."""
    for build in checks.BUILDERS:
        c = build()
        assert referee.FAULTS.get(c.id), c.id
        true = {ch.id: float(ch.equation) for ch in c.checks}
        for fault in referee.FAULTS[c.id]:
            faulty = {k: float(ch.equation) for k, ch in referee.faulty_checks(c, fault).items()}
            changed = [k for k, v in true.items() if k in faulty and not math.isclose(faulty[k], v, rel_tol=1e-9)]
            assert changed, (c.id, fault.label)


def test_the_eq13_offset_faults_are_seen_by_the_offset_copy_and_the_judgement_is_the_residual(refereed):
    """Hand-checked: the offset copy sees the offset's sign flipped, and a row agrees by its residual (SPICE's
    difference less the expected one), not by the raw difference."""
    rows = {r["id"]: r for r in refereed[checks.BUILDERS[1]]}
    row = rows["limiter-opamp-vcs-offset"]
    assert any("offset's sign flipped" in f for f in row["faults_seen"])
    assert row["rel_diff"] > row["rtol"] and row["agrees"]  # 0.8 % raw, the LM358's lag expected
    assert row["residual"] == pytest.approx((row["spice"] - row["equation"]) / row["equation"]
                                            - row["expected_difference"])


def test_judge_by_hand():
    from handbook.spice.circuit import Check

    c = Check("x", "x", "V", 1.0, "x", 0.001, "why", expected=0.005)
    assert judge(c, 1.0, 1.0055)["agrees"] and not judge(c, 1.0, 1.0065)["agrees"]
    assert not judge(c, 1.0, 1.0)["agrees"]  # the expected difference missing is a difference too


def test_every_reason_ends_in_the_tolerance_it_justifies():
    """Every row's reason ends in the tolerance it argues for, equal to rtol: a consistency check of the text (a
    reason whose number drifted from the code shows), not a proof that the tolerance is tight; that is the
    mutation test's job above, with the property test holding it from below."""
    import re

    for build in checks.BUILDERS:
        for ch in build().checks:
            stated = re.findall(r"±([0-9.]+) %", ch.why)
            assert stated, ch.id
            assert float(stated[-1]) / 100 == pytest.approx(ch.rtol, rel=0.05), (ch.id, stated[-1], ch.rtol)


def test_a_check_too_loose_to_referee_sees_nothing(ngspice):
    """The mutation test can fail: the op-amp limiter with every tolerance at ±1000 % sees none of its faults."""
    from dataclasses import replace

    from handbook.spice import limiter
    from handbook.spice.circuit import measured

    c = limiter.opamp()
    loose = replace(c, checks=tuple(replace(ch, rtol=10.0) for ch in c.checks),
                    rebuild=lambda: replace(c.rebuild(), checks=tuple(replace(ch, rtol=10.0) for ch in c.rebuild().checks)))
    assert not any(referee.seen(loose, measured(c)).values())
    assert any(referee.seen(c, measured(c)).values())
