"""Every bad input raises TaskError at the right TOML path, saying what would be valid."""
from __future__ import annotations

import pytest

from reportgen.errors import TaskError, UnknownKeyError
from reportgen.taskfile import parse_task

from taskfile_cases import DELETE, SLOTTED, edit, example, expect_error

M = "mechanism"
L = (M, "link")

# (edit path, new value or DELETE, expected TaskError.path, fragments of the message)
CASES = [
    # lengths, masses, inertias: zero, negative, wrong types
    (L + (0, "length"), 0, "mechanism.link[0].length", ["got 0", "[1e-06, 1000]", "in m"]),
    (L + (0, "length"), -0.11, "mechanism.link[0].length", ["got the float -0.11", "[1e-06, 1000]"]),
    (L + (0, "length"), "0.11", "mechanism.link[0].length", ['the string "0.11"', "a number"]),
    (L + (0, "length"), True, "mechanism.link[0].length", ["got true", "a number"]),
    (L + (0, "length"), 1100, "mechanism.link[0].length", ["got 1100", "1000]"]),
    (L + (1, "mass"), 0, "mechanism.link[1].mass", ["a number > 0", "kg"]),
    (L + (1, "mass"), -8.5, "mechanism.link[1].mass", ["> 0"]),
    (L + (1, "inertia"), 0, "mechanism.link[1].inertia", ["only a slider or block", "> 0"]),
    (L + (1, "inertia"), -0.1, "mechanism.link[1].inertia", ["> 0, in kg·m²", "0 allowed for a slider"]),
    (L + (1, "inertia"), [0.1], "mechanism.link[1].inertia", ["an array", "a number"]),
    ((M, "drive", "omega"), 0, "mechanism.drive.omega", ["≠ 0", "rad/s"]),
    ((M, "drive", "omega"), "18", "mechanism.drive.omega", ["a number"]),
    ((M, "drive", "omega"), DELETE, "mechanism.drive.omega", ["is missing", "a number"]),
    ((M, "g"), -9.81, "mechanism.g", ["[0, 50]"]),
    ((M, "points", "A"), [0.0], "mechanism.points.A", ["has 1 element", "[x, y]"]),
    ((M, "points", "A"), [0.0, 1100.0], "mechanism.points.A[1]", ["[-1000, 1000]", "in m"]),
    ((M, "points", "A"), [0.0, "y"], "mechanism.points.A[1]", ['the string "y"']),
    ((M, "points"), {}, "mechanism.points", ["is empty"]),
    ((M, "mass_rules", "q"), 0, "mechanism.mass_rules.q", ["> 0", "kg/m"]),
    ((M, "mass_rules", "slider_factor"), -6, "mechanism.mass_rules.slider_factor", ["> 0"]),
    # analysis
    (("analysis", "positions"), 2, "analysis.positions", ["got 2", "3..360"]),
    (("analysis", "positions"), 100000, "analysis.positions", ["3..360"]),
    (("analysis", "positions"), 8.0, "analysis.positions", ["the float 8.0", "an integer"]),
    (("analysis", "start"), "begin", "analysis.start", ['"extreme"', "a number"]),
    (("analysis", "start"), "extrem", "analysis.start", ['did you mean "extreme"']),
    (("analysis", "start"), True, "analysis.start", ["got true"]),
    (("analysis", "start"), 400, "analysis.start", ["[-360, 360]"]),
    (("analysis", "force_position"), 8, "analysis.force_position", ["got 8", "0..7", '"max-load"']),
    (("analysis", "force_position"), -1, "analysis.force_position", ["0..7"]),
    (("analysis", "force_position"), 2.0, "analysis.force_position", ["the float 2.0"]),
    (("analysis", "force_position"), "max_load", "analysis.force_position", ['did you mean "max-load"']),
    (("analysis", "force_position"), "max", "analysis.force_position", ['did you mean "max-load"']),
    # dynamics
    (("dynamics", "delta"), 0, "dynamics.delta", ["(0, 1)"]),
    (("dynamics", "delta"), 1, "dynamics.delta", ["(0, 1)"]),
    (("dynamics", "delta"), 1.5, "dynamics.delta", ["(0, 1)"]),
    (("dynamics", "delta"), DELETE, "dynamics.delta", ["is missing", "(0, 1)"]),
    (("dynamics", "crank_inertia"), -2.2, "dynamics.crank_inertia", ["≥ 0"]),
    (("dynamics", "flywheel", "shape"), "diks", "dynamics.flywheel.shape", ['did you mean "disk"', '"rim"']),
    (("dynamics", "flywheel", "density"), 0, "dynamics.flywheel.density", ["> 0"]),
    (("dynamics", "flywheel"), "disk", "dynamics.flywheel", ["a table"]),
    # gears
    (("gears", "z1"), 4, "gears.z1", ["got 4", "5..1000"]),
    (("gears", "z1"), 13.0, "gears.z1", ["the float 13.0", "an integer"]),
    (("gears", "z2"), False, "gears.z2", ["got false"]),
    (("gears", "z2"), DELETE, "gears.z2", ["is missing", "an integer"]),
    (("gears", "module"), 0, "gears.module", ["(0, 1000]", "mm"]),
    (("gears", "module"), -9, "gears.module", ["(0, 1000]"]),
    (("gears", "x1"), "automatic", "gears.x1", ['"auto"', "a number"]),
    (("gears", "alpha_deg"), 90, "gears.alpha_deg", ["(0, 45)"]),
    # planetary
    (("planetary", "scheme"), "two-row", "planetary.scheme", ['"single-row"', '"two-row-int-int"']),
    (("planetary", "scheme"), "two-row-ext-inf", "planetary.scheme", ['did you mean "two-row-ext-int"']),
    (("planetary", "tolerance"), 0, "planetary.tolerance", ["(0, 1)"]),
    (("planetary", "tolerance"), -0.05, "planetary.tolerance", ["(0, 1)"]),
    (("planetary", "satellites"), 0, "planetary.satellites", ['"auto"', "1..12"]),
    (("planetary", "satellites"), 13, "planetary.satellites", ["1..12"]),
    (("planetary", "satellites"), 3.0, "planetary.satellites", ["the float 3.0"]),
    (("planetary", "satellites"), "three", "planetary.satellites", ['"auto"']),
    (("planetary", "ratio"), 1, "planetary.ratio", ['"auto"', "> 1"]),
    (("planetary", "ratio"), 0.5, "planetary.ratio", ["> 1"]),
    (("planetary", "ratio"), "manual", "planetary.ratio", ['"auto"']),
    (("planetary", "motor_rpm"), DELETE, "planetary.motor_rpm", ["is missing", 'ratio = "auto"']),
    (("planetary", "module"), 0, "planetary.module", ["(0, 1000]"]),
    # words
    (L + (4, "kind"), "slidr", "mechanism.link[4].kind", ['did you mean "slider"', '"slotted"']),
    (("document", "language"), "de", "document.language", ['"ru"', '"uk"', '"en"']),
    (("document", "year"), "2026", "document.year", ["an integer"]),
    (("document", "title"), 5, "document.title", ["a string"]),
    ((M, "load", 0, "stroke"), "work", "mechanism.load[0].stroke", ['did you mean "working"', '"idle"']),
    ((M, "load", 0, "kind"), "pressure", "mechanism.load[0].kind", ['"resistance"', '"force"', '"moment"']),
    # the resistance law
    ((M, "load", 0, "law"), [[0.0, 0.0], [1.5, 1.0]], "mechanism.load[0].law[1][0]", ["[0, 1]"]),
    ((M, "load", 0, "law"), [[0.0, -0.1], [1.0, 1.0]], "mechanism.load[0].law[0][1]", ["[0, 1]"]),
    ((M, "load", 0, "law"), [[0, 0], [0.5, 0.5], [0.5, 1], [1, 1]], "mechanism.load[0].law[2][0]",
     ["increasing strictly"]),
    ((M, "load", 0, "law"), [[0, 0], [0.7, 0.5], [0.3, 1], [1, 1]], "mechanism.load[0].law[2][0]",
     ["0.3 does not follow 0.7"]),
    ((M, "load", 0, "law"), [[0.2, 0], [1, 1]], "mechanism.load[0].law[0][0]", ["stroke fraction 0"]),
    ((M, "load", 0, "law"), [[0, 0], [0.9, 1]], "mechanism.load[0].law[1][0]", ["stroke fraction 1"]),
    ((M, "load", 0, "law"), [[0, 0]], "mechanism.load[0].law", ["has 1 element", "at least 2"]),
    ((M, "load", 0, "law"), [[0, 0, 1], [1, 1]], "mechanism.load[0].law[0]", ["has 3 elements"]),
    ((M, "load", 0, "force"), 0, "mechanism.load[0].force", ["> 0", "N"]),
    ((M, "load", 0, "force"), DELETE, "mechanism.load[0]", ["neither force nor moment", "exactly one"]),
    ((M, "load", 2, "value"), "-40", "mechanism.load[2].value", ["a number"]),
    ((M, "load", 1, "vector"), [500.0], "mechanism.load[1].vector", ["[x, y]"]),
    # a single table where an array of tables belongs
    ((M, "link"), {"id": 1}, "mechanism.link", ["single table", "[[mechanism.link]]"]),
    ((M, "slide"), {"link": 5}, "mechanism.slide", ["[[mechanism.slide]]"]),
    ((M, "link"), [], "mechanism.link", ["has no links"]),
    ((M, "link"), DELETE, "mechanism.link", ["is missing"]),
    ((M, "drive"), DELETE, "mechanism.drive", ["is missing", "a table"]),
    ((M, "ground"), [], "mechanism.ground", ["has 0 elements"]),
    ((M, "ground"), "O", "mechanism.ground", ["an array of ground point names"]),
]


@pytest.mark.parametrize("where, value, path, fragments", CASES,
                         ids=[f"{c[2]}={c[1]!r}"[:60] for c in CASES])
def test_bad_value(where, value, path, fragments):
    data = example()
    edit(data, where, value)
    err = expect_error(data, path, *fragments)
    assert "expected" in str(err) or "is missing" in str(err) or "has" in str(err)


@pytest.mark.parametrize("where, key, path, suggestion", [
    (L + (0,), "lenght", "mechanism.link[0].lenght", "length"),
    ((M,), "lnk", "mechanism.lnk", "link"),
    ((), "mechansim", "mechansim", "mechanism"),
    ((M, "slide", 0, "line"), "angle", "mechanism.slide[0].line.angle", "angle_deg"),
    ((M, "slide", 0), "guid", "mechanism.slide[0].guid", "guide"),
    (("dynamics", "flywheel"), "densty", "dynamics.flywheel.densty", "density"),
    (("gears",), "Module", "gears.Module", "module"),
    (("document",), "autor", "document.autor", "author"),
    ((M, "drive"), "omega_rpm", "mechanism.drive.omega_rpm", "omega"),
    ((M, "mass_rules"), "k", "mechanism.mass_rules.k", None),
    (("analysis",), "position", "analysis.position", "positions"),
    (("planetary",), "satelites", "planetary.satelites", "satellites"),
    ((M, "load", 1), "vektor", "mechanism.load[1].vektor", "vector"),
    ((), "a key", '"a key"', None),
])
def test_unknown_key(where, key, path, suggestion):
    data = example()
    node = data
    for step in where:
        node = node[step]
    node[key] = 1
    with pytest.raises(UnknownKeyError) as info:
        parse_task(data)
    err = info.value
    assert err.path == path and err.key == key
    assert err.suggestion == suggestion
    if suggestion:
        assert f"did you mean '{suggestion}'" in str(err)
    assert "one of:" in str(err)


def test_load_key_of_another_kind():
    data = example()
    data["mechanism"]["load"][0]["value"] = 3.0
    expect_error(data, "mechanism.load[0].value", "not a key of a resistance load", "force, moment")


def test_lengths_keys_must_name_two_points_of_the_link():
    data = example(SLOTTED)
    data["mechanism"]["link"][2]["lengths"] = {"CF": 0.5}
    with pytest.raises(UnknownKeyError) as info:
        parse_task(data)
    assert info.value.path == "mechanism.link[2].lengths.CF" and "CE" in info.value.known
    data["mechanism"]["link"][2]["lengths"] = {"CEE": 0.5}
    with pytest.raises(UnknownKeyError) as info:
        parse_task(data)
    assert info.value.suggestion in ("CE", "EC")
    data["mechanism"]["link"][2]["lengths"] = {"CC": 0.5}
    with pytest.raises(UnknownKeyError):
        parse_task(data)
    data["mechanism"]["link"][2]["lengths"] = {"CE": 0.58, "EC": 0.58}
    expect_error(data, "mechanism.link[2].lengths.EC", "given twice")
    data["mechanism"]["link"][2]["lengths"] = {"CE": 0}
    expect_error(data, "mechanism.link[2].lengths.CE", "[1e-06, 1000]")
    data["mechanism"]["link"][2]["lengths"] = 0.58
    expect_error(data, "mechanism.link[2].lengths", "an inline table", "CE = …")


def test_ambiguous_lengths_key():
    data = example(SLOTTED)
    pts = data["mechanism"]["points"]
    pts["A"], pts["AB"], pts["BA"] = [1.0, 1.0], [1.2, 1.0], [1.1, 1.3]
    data["mechanism"]["link"].append({"id": 6, "kind": "coupler", "points": ["A", "AB", "BA"],
                                      "lengths": {"ABA": 0.3}})
    expect_error(data, "mechanism.link[5].lengths.ABA", "can be read as A–BA or AB–A", '"P-Q"')
    data["mechanism"]["link"][5]["lengths"] = {"A-BA": 0.3, "AAB": 0.2}   # A+AB and AB+A: one pair
    task = parse_task(data)
    assert task.mechanism.link(6).lengths == (("A", "BA", 0.3), ("A", "AB", 0.2))


def test_length_on_links_of_other_sizes():
    data = example()
    data["mechanism"]["link"][4]["length"] = 0.1
    expect_error(data, "mechanism.link[4].length", "one-point link")
    data = example(SLOTTED)
    data["mechanism"]["link"][2]["length"] = 0.58
    expect_error(data, "mechanism.link[2].length", "`lengths`")
    data = example()
    data["mechanism"]["link"][0]["lengths"] = {"OA": 0.11}
    expect_error(data, "mechanism.link[0].lengths", "both `length` and `lengths`")


def test_triangle_inequality_names_the_three_sides():
    data = example(SLOTTED)
    data["mechanism"]["link"][2]["lengths"] = {"CE": 0.5, "EG": 0.1, "CG": 0.3}
    err = expect_error(data, "mechanism.link[2].lengths", "EG = 0.1", "CG = 0.3", "CE = 0.5",
                       "EG + CG = 0.4 < CE = 0.5", "each side shorter")
    assert "from the sketch" not in str(err)
    data["mechanism"]["link"][2]["lengths"] = {"CE": 2.0}
    expect_error(data, "mechanism.link[2].lengths", "(from the sketch)", "< CE = 2")


def test_coincident_points_without_length():
    data = example(SLOTTED)
    data["mechanism"]["points"]["F"] = [0.3, 0.2]   # same place as G; link 4 = G–F has no length
    expect_error(data, "mechanism.link[3].length", "same place", "a length > 0")


@pytest.mark.parametrize("change, path, fragments", [
    (lambda d: edit(d, L + (1, "points"), ["A", "X"]), "mechanism.link[1].points[1]",
     ['no point "X" in [mechanism.points]', "one of: O, C, A, B, D"]),
    (lambda d: edit(d, L + (1, "points"), ["A", "b"]), "mechanism.link[1].points[1]", ['did you mean "B"']),
    (lambda d: edit(d, L + (1, "points"), ["A", "A"]), "mechanism.link[1].points[1]", ["listed twice"]),
    (lambda d: edit(d, L + (1, "points"), []), "mechanism.link[1].points", ["1 to 3 point names"]),
    (lambda d: edit(d, L + (1, "points"), ["A", "B", "C", "D"]), "mechanism.link[1].points", ["1 to 3"]),
    (lambda d: edit(d, L + (1, "points"), ["A", 2]), "mechanism.link[1].points[1]", ["a non-empty string"]),
    (lambda d: edit(d, (M, "ground"), ["O", "Z"]), "mechanism.ground[1]", ['no point "Z"']),
    (lambda d: edit(d, (M, "ground"), ["O", "O"]), "mechanism.ground[1]", ["listed twice"]),
    (lambda d: edit(d, L + (1, "id"), 1), "mechanism.link[1].id",
     ["id 1 is already used by mechanism.link[0]", "ids 1..5"]),
    (lambda d: edit(d, L + (4, "id"), 7), "mechanism.link[4].id", ["missing id 5", "ids 1..5"]),
    (lambda d: edit(d, L + (4, "id"), 0), "mechanism.link[4].id", ["≥ 1"]),
    (lambda d: edit(d, L + (4, "id"), DELETE), "mechanism.link[4].id", ["is missing"]),
    (lambda d: edit(d, (M, "drive", "link"), 9), "mechanism.drive.link", ["no link 9", "1..5"]),
    (lambda d: edit(d, (M, "drive", "link"), 2), "mechanism.drive.link", ["lists no ground point"]),
    (lambda d: edit(d, L + (0, "points"), ["O", "C"]) and edit(d, L + (0, "length"), DELETE),
     "mechanism.drive.link", ["2 ground points"]),
    (lambda d: edit(d, (M, "drive", "link"), 5), "mechanism.drive.link", ["lists no ground point"]),
    (lambda d: edit(d, L + (0, "com"), 1.5), "mechanism.link[0].com", ["[0, 1]", "a non-empty string"]),
    (lambda d: edit(d, L + (0, "com"), "B"), "mechanism.link[0].com", ['no point "B" in the points of this link']),
    (lambda d: edit(d, L + (4, "com"), 0.5), "mechanism.link[4].com", ['point name "D"']),
    (lambda d: edit(d, L + (4, "com"), "D") and edit(d, L + (4, "inertia"), -1), "mechanism.link[4].inertia", ["got -1", "0 allowed for a slider"]),
    # slides
    (lambda d: edit(d, (M, "slide", 0, "link"), 6), "mechanism.slide[0].link", ["no link 6"]),
    (lambda d: edit(d, (M, "slide", 0, "point"), "A"), "mechanism.slide[0].point", ['no point "A" in link 5']),
    (lambda d: edit(d, (M, "slide", 0, "line"), DELETE), "mechanism.slide[0].line", ["is missing"]),
    (lambda d: edit(d, (M, "slide", 0, "line"), [0, 0]), "mechanism.slide[0].line", ["through = [x, y]"]),
    (lambda d: edit(d, (M, "slide", 0, "line", "through"), DELETE), "mechanism.slide[0].line.through",
     ["is missing", "[x, y]"]),
    (lambda d: edit(d, (M, "slide", 0, "line", "angle_deg"), "0"), "mechanism.slide[0].line.angle_deg",
     ["a number"]),
    (lambda d: edit(d, (M, "slide", 0, "along"), ["C", "B"]), "mechanism.slide[0].along", ["guide = k > 0"]),
    (lambda d: edit(d, (M, "slide", 0, "guide"), -1), "mechanism.slide[0].guide", ["≥ 0"]),
    (lambda d: edit(d, (M, "slide", 0, "guide"), 5), "mechanism.slide[0].guide", ["cannot slide along itself"]),
    (lambda d: edit(d, (M, "slide", 0, "guide"), 8), "mechanism.slide[0].guide", ["no link 8"]),
    (lambda d: edit(d, (M, "slide", 0, "guide"), 3), "mechanism.slide[0].line", ["guide = 0"]),
    (lambda d: edit(d, (M, "slide", 0, "guide"), 3) and edit(d, (M, "slide", 0, "line"), DELETE),
     "mechanism.slide[0].along", ["is missing", "two point names of link 3"]),
    (lambda d: edit(d, (M, "slide"), [d["mechanism"]["slide"][0]] * 2), "mechanism.slide[1]",
     ["already slides on guide 0"]),
    # loads
    (lambda d: edit(d, (M, "load", 0, "link"), 6), "mechanism.load[0].link", ["no link 6"]),
    (lambda d: edit(d, (M, "load", 0, "moment"), 5.0), "mechanism.load[0]", ["both force and moment"]),
    (lambda d: edit(d, (M, "load", 1, "point"), "A"), "mechanism.load[1].point", ['no point "A" in link 5']),
    (lambda d: edit(d, (M, "load", 1, "point"), DELETE), "mechanism.load[1].point", ["or com = true"]),
    (lambda d: edit(d, (M, "load", 1, "com"), True), "mechanism.load[1].com", ["both given"]),
    (lambda d: edit(d, (M, "load", 1, "com"), 1), "mechanism.load[1].com", ["true or false"]),
    (lambda d: edit(d, (M, "load", 2, "kind"), DELETE), "mechanism.load[2].kind", ["is missing"]),
])
def test_bad_reference(change, path, fragments):
    data = example()
    change(data)
    expect_error(data, path, *fragments)


def test_slotted_along_must_be_points_of_the_guide_link():
    data = example(SLOTTED)
    data["mechanism"]["slide"][0]["along"] = ["C", "B"]
    expect_error(data, "mechanism.slide[0].along[1]", 'no point "B" in link 3', "one of: C, E, G")
    data["mechanism"]["slide"][0]["along"] = ["C", "C"]
    expect_error(data, "mechanism.slide[0].along[1]", "the same point twice")
    data["mechanism"]["slide"][0]["along"] = ["C"]
    expect_error(data, "mechanism.slide[0].along", "has 1 element")


def test_slide_point_required_when_the_link_has_several_points():
    data = example(SLOTTED)
    data["mechanism"]["slide"][0]["link"] = 1
    del data["mechanism"]["slide"][0]["point"]
    expect_error(data, "mechanism.slide[0].point", "is missing")


def test_top_level_must_be_a_table():
    with pytest.raises(TaskError) as info:
        parse_task([1, 2])  # type: ignore[arg-type]
    assert info.value.path == "" and "a table" in str(info.value)
    expect_error({"mechanism": 5}, "mechanism", "got 5", "a table")


def test_empty_lengths_table_is_refused_as_the_schema_does():
    """`lengths = {}` (found by the schema ↔ loader property test): the key spec asks for at least one
    distance, and so does the loader now."""
    data = example(SLOTTED)
    data["mechanism"]["link"][2]["lengths"] = {}
    with pytest.raises(TaskError) as info:
        parse_task(data)
    assert info.value.path == "mechanism.link[2].lengths" and "empty" in str(info.value)
