"""Each condition against an independent computation (geometry, tooth phases, plain Fractions)."""

import pytest
from hypothesis import given, settings, strategies as st

import brute
from reportgen.errors import TaskError
from reportgen.planetary.conditions import (UndercutLimits, check_adjacency, check_assembly,
                                            check_coaxial, check_undercut)
from reportgen.planetary.schemes import SCHEMES, coaxial_z3, get_scheme, willis_u1h

SCHEME_NAMES = tuple(SCHEMES)


@st.composite
def coaxial_sets(draw, scheme=None):
    name = scheme or draw(st.sampled_from(SCHEME_NAMES))
    sch = get_scheme(name)
    z2 = draw(st.integers(10, 120))
    if sch.row1 == "internal":
        z1 = draw(st.integers(z2 + 3, z2 + 200))
    else:
        z1 = draw(st.integers(10, 150))
    if not sch.two_row:
        return name, (z1, z2, coaxial_z3(sch, z1, z2, z2))
    z2p = draw(st.integers(10, 150))
    z3 = coaxial_z3(sch, z1, z2, z2p)
    if z3 < 5:
        z2p = max(5, (z1 + z2) // 3)
        z3 = coaxial_z3(sch, z1, z2, z2p)
    return name, (z1, z2, z2p, z3)


@settings(max_examples=300, deadline=None)
@given(coaxial_sets(), st.integers(1, 8))
def test_assembly_matches_tooth_phases(case, k):
    name, z = case
    if min(z) < 1:
        return
    assert check_assembly(get_scheme(name), z, k).holds == brute.assembly_by_phases(name, z, k)


@settings(max_examples=300, deadline=None)
@given(coaxial_sets(), st.integers(1, 8))
def test_adjacency_matches_geometry(case, k):
    name, z = case
    if min(z) < 1:
        return
    assert check_adjacency(get_scheme(name), z, k).holds == brute.adjacency_geometric(name, z, k)


@settings(max_examples=200, deadline=None)
@given(coaxial_sets())
def test_coaxial_and_willis(case):
    name, z = case
    sch = get_scheme(name)
    assert check_coaxial(sch, z).holds == brute.coaxial(name, z)
    assert willis_u1h(sch, z) == brute.willis(name, z)


def test_exact_assembly_accepts_what_the_single_row_form_rejects():
    # two-row ext-int, K = 4: a set where (z1 + z3)/K (the single-row form the seed applies) is
    # not whole, yet the tooth-phase brute force places the planets
    found = None
    for z1 in range(17, 30):
        for z2 in range(17, 80):
            for z2p in range(17, 60):
                z = (z1, z2, z2p, z1 + z2 + z2p)
                if (z1 + z[3]) % 4 and brute.assembly_by_phases("two-row-ext-int", z, 4):
                    found = z
                    break
            if found:
                break
        if found:
            break
    assert found is not None
    assert check_assembly(get_scheme("two-row-ext-int"), found, 4).holds


def test_exact_assembly_rejects_what_the_single_row_form_accepts():
    sch = get_scheme("two-row-ext-int")
    bad = [z for z in ((z1, z2, z2p, z1 + z2 + z2p) for z1 in range(17, 25) for z2 in range(17, 60)
                       for z2p in range(17, 40)) if (z[0] + z[3]) % 3 == 0
           and not brute.assembly_by_phases("two-row-ext-int", z, 3)]
    assert bad
    assert not any(check_assembly(sch, z, 3).holds for z in bad[:50])


def test_single_row_textbook_example():
    # z1 = 20, z2 = 30, z3 = 80, K = 4: (20 + 80)/4 = 25, u1H = 1 + 80/20 = 5 (Артоболевский)
    sch = get_scheme("single-row")
    z = (20, 30, 80)
    assert check_coaxial(sch, z).holds and check_assembly(sch, z, 4).quotient == 25
    assert willis_u1h(sch, z) == 5
    assert check_undercut(sch, z).holds is False            # ring 80 < 85: the course's limit
    assert check_undercut(sch, z, UndercutLimits(internal_min=80)).holds


def test_undercut_limits_are_named():
    sch = get_scheme("two-row-int-int")
    items = {i.what: i for i in check_undercut(sch, (100, 95, 17, 22)).items}
    assert not items["1−2"].holds and items["1−2"].value == 5 and items["1−2"].limit == 8
    assert not items["3"].holds and items["3"].limit == 85
    with pytest.raises(TaskError, match="planetary.limits.internal_min"):
        UndercutLimits(internal_min=0)


def test_adjacency_boundary_is_strict():
    # K = 6: (2a/m)/2 = z_p + 2 exactly → tips touch → rejected
    sch = get_scheme("single-row")
    z = (24, 22, 68)        # 2a/m = 46, z2 + 2 = 24 → 46·sin30° = 23 < 24
    assert not check_adjacency(sch, z, 6).holds
    z = (26, 22, 70)        # 2a/m = 48 → 48·0.5 = 24 = z2 + 2: touching
    assert not check_adjacency(sch, z, 6).holds
    assert not brute.adjacency_geometric("single-row", z, 6)
    assert check_adjacency(sch, (28, 22, 72), 6).holds
