"""Scene validation: every malformed scene gets one message naming key, value and what is
allowed; every bundled scene validates; docs/scenes.md documents every key."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from charts.cli.main import bundled_scenes
from charts.runs.scene import EFFECTS, SCHEMA, SceneError, load_scene, parse_scene

from scenarios import EXACT_N3

DOCS = Path(__file__).resolve().parent.parent / "docs" / "scenes.md"


def base(**over):
    """A minimal valid scene dict, with sections replaced/extended by ``over``."""
    d = {"system": {"n": 3}, "run": {"t_final": 1.0}, "effects": {"waveforms": {}}}
    for k, v in over.items():
        d[k] = v
    return d


def error_of(data) -> str:
    with pytest.raises(SceneError) as exc:
        parse_scene(data, source="s.toml")
    msg = str(exc.value)
    assert msg.startswith("s.toml"), msg
    assert "\n" not in msg, "one message, one line"
    return msg


def test_minimal_scene_fills_defaults():
    sc = parse_scene(base())
    assert sc.system == {"n": 3, "masses": [1.0, 1.0, 1.0], "speed": 1.0}
    assert sc.integrator["method"] == "rk4" and sc.integrator["dt"] == 0.01
    assert sc.run["sample_dt"] == 0.01 and sc.run["checkpoint_every"] == pytest.approx(0.05)
    assert sc.effects == {"waveforms": {"rotors": [0, 1, 2], "t_window": 1.0}}


@pytest.mark.parametrize("data, pieces", [
    # unknown key with a suggestion, at every level
    (base(system={"n": 3, "mases": [1, 1, 1]}), ["'mases'", "[system]", "did you mean 'masses'"]),
    (base(integrater={"dt": 0.01}), ["'integrater'", "did you mean 'integrator'"]),
    (base(effects={"lyapunof": {}}), ["'lyapunof'", "[effects]", "did you mean 'lyapunov'"]),
    (base(effects={"lyapunov": {"n_exponent": 1}}), ["[effects.lyapunov]", "'n_exponent'",
                                                     "did you mean 'n_exponents'"]),
    (base(run={"t_final": 1.0, "zzz": 1}), ["'zzz'", "allowed: checkpoint_every"]),
    # wrong types
    (base(system={"n": 3.0}), ["[system] n = 3.0", "expected an integer"]),
    (base(system={"n": "3"}), ["[system] n = '3'", "expected an integer"]),
    (base(system={"n": True}), ["[system] n = True", "expected an integer"]),
    (base(run={"t_final": "long"}), ["[run] t_final = 'long'", "expected a number"]),
    (base(integrator={"project": 1}), ["[integrator] project = 1", "true or false"]),
    (base(system={"n": 3, "masses": [1, "a", 1]}), ["[system] masses", "a list of numbers"]),
    (base(effects={"waveforms": 3}), ["[effects] waveforms = 3", "true, false or a table"]),
    (base(system=[3]), ["[system] must be a table"]),
    # out of range
    (base(system={"n": 2}), ["[system] n = 2", "an integer in 3..1048576"]),
    (base(system={"n": 3, "masses": [1, -1, 1]}), ["[system] masses = [1.0, -1.0, 1.0]", "> 0"]),
    (base(system={"n": 3, "masses": [1, 1]}), ["[system] masses", "n = 3 positive numbers"]),
    (base(system={"n": 3, "speed": 0}), ["[system] speed = 0.0", "> 0"]),
    (base(run={"t_final": -1}), ["[run] t_final = -1.0", "> 0"]),
    (base(integrator={"dt": 0}), ["[integrator] dt = 0.0", "> 0"]),
    (base(integrator={"method": "rk45"}), ["[integrator] method = 'rk45'", "'rk4', 'dop853'",
                                           "did you mean 'rk4'"]),
    (base(integrator={"formulation": "intrinsic"}), ["formulation = 'intrinsic'", "'chart'"]),
    # NaN / inf (TOML has nan and inf literals)
    (base(run={"t_final": math.nan}), ["[run] t_final = nan", "a finite number"]),
    (base(integrator={"dt": math.inf}), ["[integrator] dt = inf", "a finite number"]),
    (base(initial={"theta": [math.nan, 0, 0], "u": [0, 0, 0]}),
     ["[initial] theta", "finite numbers"]),
    # missing required
    (base(system={}), ["[system] n is required"]),
    (base(run={}), ["[run] t_final is required"]),
    (base(effects={}), ["requests no effect"]),
])
def test_malformed_scene_message(data, pieces):
    msg = error_of(data)
    for piece in pieces:
        assert piece in msg, (piece, msg)


# An exact point of the N = 3 manifold and a tangent velocity.
THETA, U = (list(v) for v in EXACT_N3)


def test_explicit_state_accepted_and_speed_derived():
    sc = parse_scene(base(initial={"theta": THETA, "u": U}))
    assert sc.initial["seed"] is None
    assert sc.system["speed"] == pytest.approx(math.sqrt(2.0))


@pytest.mark.parametrize("initial, system, pieces", [
    ({"theta": [0.0, 0.0, 0.0], "u": U}, {}, ["[initial] theta = [0.0, 0.0, 0.0]",
                                               "off the manifold", "sum(cos theta) = 3.0"]),
    ({"theta": THETA, "u": [1.0, 1.0, 0.0]}, {}, ["[initial] u = [1.0, 1.0, 0.0]",
                                                   "not tangent"]),
    ({"theta": THETA}, {}, ["[initial] u is required when [initial] theta is given"]),
    ({"theta": THETA, "u": U, "seed": 1}, {}, ["[initial] seed = 1", "one or the other"]),
    ({"theta": THETA[:2], "u": U}, {}, ["[initial] theta", "n = 3 numbers"]),
    ({"theta": THETA, "u": U}, {"speed": 2.0}, ["[system] speed = 2.0", "explicit [initial] u"]),
    ({"theta": THETA, "u": [0.0, 0.0, 0.0]}, {}, ["[initial] u", "nonzero"]),
    ({"seed": -1}, {}, ["[initial] seed = -1", ">= 0"]),
])
def test_bad_initial_state(initial, system, pieces):
    msg = error_of(base(initial=initial, system={"n": 3, **system}))
    for piece in pieces:
        assert piece in msg, (piece, msg)


@pytest.mark.parametrize("over, pieces", [
    (dict(integrator={"method": "rk4", "rtol": 1e-8}), ["[integrator] rtol", "method = 'dop853'"]),
    (dict(integrator={"method": "dop853", "dt": 0.01}), ["[integrator] dt", "adaptive"]),
    (dict(run={"t_final": 1.0, "sample_dt": 0.015}), ["[run] sample_dt = 0.015",
                                                       "multiple of [integrator] dt"]),
    (dict(run={"t_final": 1.005, "sample_dt": 0.01}), ["[run] t_final = 1.005", "nearest"]),
    (dict(run={"t_final": 1.0, "checkpoint_every": 0.333}), ["checkpoint_every = 0.333"]),
    (dict(effects={"switches": {}}), ["switches", "formulation = 'chart'"]),
    (dict(effects={"lyapunov": {}}, integrator={"formulation": "chart"}),
     ["lyapunov", "formulation = 'ambient', method = 'rk4'"]),
    (dict(effects={"curvature": {"n_directions": 2}}), ["[effects.curvature] n_directions = 2",
                                                        "1..1"]),
    (dict(effects={"lyapunov": {"n_exponents": 3}}), ["n_exponents = 3", "1..2",
                                                       "inner_product = 'full'"]),
    (dict(effects={"lyapunov": {"n_exponents": 5, "inner_product": "full"}}),
     ["n_exponents = 5", "1..4"]),
    (dict(effects={"waveforms": {"rotors": [0, 3]}}), ["rotors = [0, 3]", "0..2"]),
    (dict(effects={"spectrum": {"nperseg": 512}}), ["nperseg = 512", "at most", "100"]),
    (dict(effects={"curvature": {"route": "exakt"}}), ["route = 'exakt'", "did you mean 'exact'"]),
])
def test_inconsistent_scene(over, pieces):
    msg = error_of(base(**over))
    for piece in pieces:
        assert piece in msg, (piece, msg)


def test_effect_true_and_false():
    sc = parse_scene(base(effects={"waveforms": True, "drift": False, "lyapunov": {}}))
    assert set(sc.effects) == {"waveforms", "lyapunov"}
    assert sc.effects["lyapunov"]["n_exponents"] == 1          # N − 2


def test_load_scene_file_errors(tmp_path):
    with pytest.raises(SceneError, match="no such scene file"):
        load_scene(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[system\nn = 3\n")
    with pytest.raises(SceneError, match="not valid TOML"):
        load_scene(bad)
    good = tmp_path / "mine.toml"
    good.write_text("[system]\nn = 4\n[run]\nt_final = 2\n[effects.drift]\n")
    sc = load_scene(good)
    assert sc.name == "mine" and sc.system["n"] == 4


def test_every_bundled_scene_validates():
    scenes = bundled_scenes()
    names = set(scenes)
    for fig in ("fig2", "fig3", "fig4", "fig5", "table"):
        assert {f"{fig}-n{n}" for n in (3, 4, 5)} <= names
    assert sum(n.startswith("hard-") for n in names) >= 5
    for name, path in scenes.items():
        sc = load_scene(path)
        assert sc.name == name and sc.description


def test_reference_page_documents_every_key():
    text = DOCS.read_text()
    for section, keys in SCHEMA.items():
        assert f"[{section}]" in text, section
        for key in keys:
            assert re.search(rf"`{key}`", text), f"[{section}] {key} missing from docs/scenes.md"
    for name in bundled_scenes():
        assert f"`{name}`" in text, f"bundled scene {name} missing from docs/scenes.md"
    for effect, keys in EFFECTS.items():
        assert f"[effects.{effect}]" in text, effect
        for key in keys:
            assert re.search(rf"`{key}`", text), f"[effects.{effect}] {key} missing"


def test_reference_page_gives_the_schemas_defaults():
    """The default column of every key table in docs/scenes.md shows the schema's default as
    a scene gets it (an API default resolved from the signature, and that function named)."""
    from charts.runs.scene_schema import API, FromAPI

    def fmt(v):
        if isinstance(v, bool):
            return f"`{str(v).lower()}`"
        return f'`"{v}"`' if isinstance(v, str) else f"`{v!r}`"

    section, seen = None, 0
    for line in DOCS.read_text().splitlines():
        m = re.match(r"^#+ \[(.+)\]$", line)
        if m:
            section = m.group(1)
        m = re.match(r"^\| `(\w+)` \|[^|]*\| ([^|]*) \|", line)
        if not (m and section):
            continue
        table = EFFECTS[section[8:]] if section.startswith("effects.") else SCHEMA.get(section)
        if table is None or m.group(1) not in table:
            continue
        key, cell = table[m.group(1)], m.group(2)
        if key.required:
            assert cell == "**required**", line
        elif key.value is not None:
            assert cell.startswith(fmt(key.value)), (line, fmt(key.value))
            if isinstance(key.default, FromAPI):
                assert f"`{API[key.default.effect].split(':')[1]}`" in cell, line
            if key.linkage is not None:         # a linkage scene's own default, and its call
                assert (f"linkage: {fmt(key.linkage.value)} "
                        f"(`{API[key.linkage.effect].split(':')[1]}`)") in cell, line
        seen += 1
    assert seen == sum(len(t) for t in SCHEMA.values()) + sum(len(t) for t in EFFECTS.values())


def test_every_key_level_problem_is_reported_at_once():
    """Unknown keys, wrong types and bad values in several sections and effects come back
    together in one SceneError (one line, counted), not one per run of the command."""
    with pytest.raises(SceneError) as err:
        parse_scene({"system": {"n": "four", "mases": [1.0]}, "run": {"t_final": -1.0},
                     "effects": {"lyapunv": True, "curvature": {"n_directions": "x"}}},
                    source="s.toml")
    msg = str(err.value)
    assert msg.startswith("s.toml: 5 problems: ") and "\n" not in msg
    for part in ("'mases'", "[system] n = 'four'", "[run] t_final = -1.0", "'lyapunv'",
                 "[effects.curvature] n_directions = 'x'"):
        assert part in msg, part
    with pytest.raises(SceneError) as one:             # a single problem keeps its own line
        parse_scene({"system": {"n": 2}, "run": {"t_final": 1.0}, "effects": {"drift": True}},
                    source="s.toml")
    assert str(one.value).startswith("s.toml: [system] n = 2 is not allowed")


@pytest.mark.parametrize("system, message", [
    ({"n": 3, "masses": [1.0] * 1_000_000}, "[system] masses = [1.0, 1.0,"),
    ({"n": 3, "level": 10**400}, "an integer beyond a float's range is not"),
    ({"n": 3, "masses": [1.0, 2.0, 10**400]}, "a list of finite numbers"),
    ({"n": 10**400}, "an integer in 3..1048576"),
])
def test_huge_values_are_refused_in_one_short_line(system, message):
    """A value beyond a float's range is a SceneError, never an OverflowError, and a long
    value is shown in brief (80 characters), not echoed."""
    with pytest.raises(SceneError) as info:
        parse_scene({"system": system, "run": {"t_final": 1.0}, "effects": {"waveforms": {}}})
    assert message in str(info.value) and len(str(info.value)) < 300
