"""The sections of a study's report, checked as data against the study's own Dataset and analysis code, and
against the closed form of the study: a ball thrown up at speed v under gravity g (tests/data/study),
whose final height v T - g T^2 / 2 is largest at the fastest throw under the weakest gravity."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from jointplay.errors import ModelError
from jointplay.report.blocks import Plot, Table, Text
from jointplay.report.study import study_sections
from jointplay.study import Study, load_study, open_study

DATA = Path(__file__).parent / "data" / "study"
T_END = 0.2  # [s], the model file's


def height(v, g, t):
    """Height [m] at t [s] of a ball thrown up at v [m/s] under gravity g [m/s^2, > 0]."""
    return v * t - 0.5 * g * t**2


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    """The throw study (3 speeds x 3 gravities) run into a folder, as `jointplay sweep` leaves it."""
    folder = tmp_path_factory.mktemp("throw") / "study"
    load_study(DATA / "throw_study.toml").run(folder)
    return folder


@pytest.fixture(scope="module")
def report(swept):
    return study_sections(swept)


def section(sections, title: str):
    found = [s for s in sections if s.title == title]
    assert len(found) == 1, [s.title for s in sections]
    return found[0]


def blocks(sec, kind) -> list:
    return [b for b in sec.blocks if isinstance(b, kind)]


def test_the_definition_states_factors_in_units_design_and_responses(report):
    title, sections = report
    assert title == "Study: throw"
    definition = section(sections, "Study definition")
    factors, responses = blocks(definition, Table)
    assert factors.rows == [["speed", "bodies.ball.velocity.1", "1 .. 3 m/s", "m/s", ""],
                            ["g", "model.gravity.1", "-9 m/s^2, -10 m/s^2, -11 m/s^2", "m/s^2", ""]]
    assert [r[:2] for r in responses.rows] == [["height", "m"], ["final_height", "m"]]
    text = blocks(definition, Text)[0].text
    assert "9 cases" in text and "full_factorial" in text and "t_end = 0.2 s" in text and "ball.y" in text


def test_the_design_table_holds_the_datasets_values(swept, report):
    ds = open_study(swept)
    table = blocks(section(report[1], "Design table"), Table)[0]
    assert table.columns == ["case", "speed [m/s]", "g [m/s^2]", "g level", "height [m]", "final_height [m]",
                             "status", "steps"]
    assert len(table.rows) == ds.sizes["case"] == 9
    for k, row in enumerate(table.rows):
        assert row[0] == k and row[1] == ds["speed"].values[k] and row[2] == ds["g"].values[k]
        assert row[3] == str(ds["g_label"].values[k])
        assert row[4] == ds["height"].values[k] and row[5] == ds["final_height"].values[k]
        assert row[6:] == ["done", int(ds["steps"].values[k])]
        # and the values are the physics': the closed form of the final height
        assert row[5] == pytest.approx(height(row[1], -row[2], T_END), abs=1e-9)


def test_the_sensitivities_are_the_study_codes(swept, report):
    from jointplay.study.sensitivity import sobol_indices

    ds = open_study(swept)
    sec = section(report[1], "Sensitivities")
    tables = blocks(sec, Table)
    assert len(tables) == 2  # both surfaces are trustworthy, so both responses have indices
    for table, response in zip(tables, ["height", "final_height"], strict=True):
        expected = sobol_indices(ds, response)
        assert [row[0] for row in table.rows] == list(expected.factor_names)
        assert [row[1] for row in table.rows] == list(expected.first_order)
        assert [row[3] for row in table.rows] == list(expected.total)
        # the bootstrap's half-widths too: it is seeded, so another call gives the same
        assert [row[2] for row in table.rows] == list(expected.first_order_conf)
        assert [row[4] for row in table.rows] == list(expected.total_conf)
        assert "fitted quadratic surface" in table.caption and "N = 8192" in table.caption
    # the final height's variance over the design's box, in closed form: T^2 Var(v) against T^4/4 Var(g)
    var_v, var_g = (3 - 1) ** 2 / 12, (11 - 9) ** 2 / 12
    share_v = T_END**2 * var_v / (T_END**2 * var_v + T_END**4 / 4 * var_g)
    assert tables[1].rows[0][3] == pytest.approx(share_v, abs=0.03)
    bars = blocks(sec, Plot)[1].figure
    assert bars.layout.yaxis.title.text == "share of the variance of final_height [-] (0 .. 1)"
    assert list(bars.data[1].y) == pytest.approx(list(sobol_indices(ds, "final_height").total))


def test_the_figures_carry_axis_titles_with_units(report):
    plots = blocks(section(report[1], "Response surfaces"), Plot)
    assert len(plots) == 4  # per response: against each factor, and the surface over the two factors
    against = plots[2].figure
    assert against.layout.xaxis.title.text == "speed [m/s]" and against.layout.xaxis2.title.text == "g [m/s^2]"
    assert against.layout.yaxis.title.text == "final_height [m]"
    assert list(against.layout.xaxis2.ticktext) == ["-11 m/s^2", "-10 m/s^2", "-9 m/s^2"]
    contour = plots[3].figure
    assert contour.layout.xaxis.title.text == "speed [m/s]" and contour.layout.yaxis.title.text == "g [m/s^2]"
    assert contour.data[0].colorbar.title.text == "final_height [m]"
    # the surface is drawn in real units over the factors' ranges, and equals the closed form (it is linear)
    surface = contour.data[0]
    assert (surface.x[0], surface.x[-1], surface.y[0], surface.y[-1]) == pytest.approx((1, 3, -9, -11))
    v, g = np.meshgrid(surface.x, surface.y)
    np.testing.assert_allclose(surface.z, height(v, -g, T_END), atol=1e-9)
    assert "largest total Sobol' indices" in plots[3].caption


def test_without_an_optimisation_the_best_cases_are_swepts(swept, report):
    from jointplay.study.summary import best_cases

    ds = open_study(swept)
    tables = blocks(section(report[1], "Best cases"), Table)
    for table, response in zip(tables, ["height", "final_height"], strict=True):
        assert [row[0] for row in table.rows] == best_cases(ds, response)
        assert [row[-1] for row in table.rows] == [ds[response].values[k] for k in best_cases(ds, response)]
    # the lowest final height: the slowest throw under the strongest gravity
    assert tables[1].rows[0][1:3] == ["1 m/s", "-11 m/s^2"]


def test_the_optimum_is_the_one_jointplay_optimize_found(tmp_path):
    """`jointplay optimize` on the study's folder, then the report: the optimum it wrote, at the fastest throw
    and the weakest gravity, predicted by the surface and verified by a run."""
    folder = tmp_path / "o"
    done = subprocess.run([str(Path(sys.executable).with_name("jointplay")), "optimize", str(DATA / "throw_study.toml"),
                           "-o", str(folder), "-q", "--workers", "1"], capture_output=True, text=True, timeout=300,
                          env={**os.environ, "COLUMNS": "160"})
    assert done.returncode == 0, done.stderr
    written = json.loads((folder / "optimum.json").read_text())
    sec = section(study_sections(folder)[1], "Optimum")
    values, responses = blocks(sec, Table)
    assert values.rows == [["speed", written["labels"]["speed"]], ["g", "-9 m/s^2"]]
    assert written["values"]["speed"] == pytest.approx(3.0, abs=1e-6)
    final = responses.rows[1]
    assert final[:3] == ["final_height [m]", written["predicted"]["final_height"], written["verified"]["final_height"]]
    assert final[2] == pytest.approx(height(3.0, 9.0, T_END), abs=1e-6)
    assert abs(final[3]) < 1e-6  # [%]: the linear surface predicts the run
    assert written["method"] in blocks(sec, Text)[0].text


def test_failed_cases_are_listed_and_left_out(tmp_path):
    folder = tmp_path / "failing"
    Study(DATA / "throw.toml", factors=[{"name": "mass", "path": "bodies.ball.mass",
                                         "levels": ["1 kg", "-1 kg", "2 kg", "3 kg"]}],
          responses=[{"name": "final_height", "kind": "final", "channel": "ball.y"}]).run(folder)
    sections = study_sections(folder)[1]
    failed = blocks(section(sections, "Failed cases"), Table)[0]
    assert [row[:2] for row in failed.rows] == [[1, "-1 kg"]]
    assert "bodies.ball.mass" in failed.rows[0][2] and "1 of 4 cases failed" in failed.caption
    design = blocks(section(sections, "Design table"), Table)[0]
    assert design.columns == ["case", "mass [kg]", "mass level", "final_height [m]", "status", "steps"]
    assert math.isnan(design.rows[1][3]) and design.rows[1][4] == "failed"
    # a one-factor study has no contour: one figure against the factor
    assert len(blocks(section(sections, "Response surfaces"), Plot)) == 1


def test_a_missing_or_unfinished_folder_is_a_located_model_error(tmp_path, swept):
    with pytest.raises(ModelError) as caught:
        study_sections(tmp_path / "nowhere")
    assert caught.value.problems[0].location == str(tmp_path / "nowhere")
    with pytest.raises(ModelError) as caught:
        study_sections(tmp_path)
    assert caught.value.problems[0].location == str(tmp_path / "study.json")
    assert "not a study folder" in caught.value.problems[0].message
    unfinished = tmp_path / "unfinished"
    (unfinished / "cases").mkdir(parents=True)
    (unfinished / "study.json").write_text((swept / "study.json").read_text())
    with pytest.raises(ModelError) as caught:
        study_sections(unfinished)
    assert caught.value.problems[0].location == str(unfinished / "study.nc")
    assert "0 of 9 cases done" in caught.value.problems[0].message


def test_an_optimum_file_of_another_study_is_a_located_model_error(tmp_path, swept):
    import shutil

    folder = tmp_path / "copy"
    shutil.copytree(swept, folder)
    (folder / "optimum.json").write_text(json.dumps({"method": "surface", "values": {"clearance": 1e-4}}))
    with pytest.raises(ModelError) as caught:
        study_sections(folder)
    assert caught.value.problems[0].location == str(folder / "optimum.json")
