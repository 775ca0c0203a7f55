"""The Python API: builder errors, options, results, errors that keep results."""

import json

import numpy as np
import pytest

import flores_slider_crank_dry as flores
import jointplay as jp
from jointplay import functions as fn
from jointplay import laws


def pendulum(**body) -> jp.Model:
    m = jp.Model("pendulum", gravity=(0, -9.81))
    m.add_ground_point("O", (0, 0))
    m.add_body("bar", mass=1.0, inertia=0.02, position=(0.25, 0), points={"O": (-0.25, 0)}, **body)
    m.add_revolute("pin", "ground.O", "bar.O")
    return m


def test_model_errors_list_every_problem_with_its_element_name():
    m = pendulum()
    m.add_revolute("hinge", "bar.Q", "nothing.P")
    m.add_driver("motor", "nojoint", fn.constant_speed(1.0))
    with pytest.raises(jp.ModelError) as info:
        m.simulate(1.0)
    assert [str(p) for p in info.value.problems] == [
        'joints.hinge.first: unknown point "bar.Q" (body "bar" has no such point)',
        'joints.hinge.second: unknown point "nothing.P" (no body named "nothing")',
        'drivers.motor.joint: unknown revolute or translational joint "nojoint"']


def test_bad_builder_argument_is_an_error_at_once_by_element_name():
    with pytest.raises(jp.ModelError) as info:
        pendulum().add_body("ghost", mass=0.0, inertia=1.0)
    assert [str(p) for p in info.value.problems] == ["bodies.ghost.mass: must be > 0, got 0 kg"]


def test_bad_simulation_options_are_model_errors_naming_the_option():
    with pytest.raises(jp.ModelError) as info:
        pendulum().simulate(-1.0, method="euler", rtol=0.0)
    locations = {p.location for p in info.value.problems}
    assert locations == {"simulation.t_end", "simulation.method", "simulation.rtol"}
    assert "must be one of ['adams', 'bdf', 'dopri5', 'generalized_alpha'], got 'euler'" in str(info.value)


def test_every_method_swings_the_pendulum_alike():
    runs = {method: pendulum().simulate(1.0, method=method, rtol=1e-9, atol=1e-12) for method in ("dopri5", "adams", "bdf")}
    final = {method: results["bar.angle"][-1] for method, results in runs.items()}
    assert abs(final["dopri5"] + 1.0) < 1.5  # it swung
    for method in ("adams", "bdf"):
        assert final[method] == pytest.approx(final["dopri5"], abs=1e-6), method
    assert runs["bdf"].statistics["jacobian_evaluations"] >= 1
    assert runs["dopri5"].statistics["jacobian_evaluations"] == 0


def test_results_give_arrays_units_and_an_xarray_dataset(tmp_path):
    results = pendulum().simulate(0.5, output_step=0.01)
    assert results.time.size == 51
    assert results["bar.angle"].shape == results.time.shape
    assert results.unit("bar.ax") == "m/s^2" and results.unit("pin.fx") == "N"
    with pytest.raises(KeyError, match="did you mean bar.omega"):
        results["bar.omegaa"]
    ds = results.to_xarray()
    assert ds["bar.omega"].attrs["units"] == "rad/s"
    assert ds.attrs["statistics_accepted_steps"] == results.statistics["accepted_steps"]
    path = tmp_path / "pendulum.nc"
    results.save(path)
    import xarray as xr

    with xr.open_dataset(path, engine="scipy") as back:
        np.testing.assert_array_equal(back["bar.angle"].values, results["bar.angle"])
        assert back["pin.fy"].attrs["units"] == "N"


def test_a_failing_simulation_keeps_what_was_computed():
    # a clearance joint whose penetration bound is absurdly small stops at the first impact
    model = flores.build_model()
    model.joint("B")["max_penetration"] = 1e-9
    with pytest.raises(jp.SimulationError) as info:
        flores.simulate(model)
    error = info.value
    assert error.kind == "ExcessivePenetration" and error.element == "B"
    assert error.time == pytest.approx(2.27e-4, rel=0.01)
    assert error.results is not None and error.results.time[-1] <= error.time
    assert error.results["slider.x"].size == error.results.time.size > 10
    assert "penetration" in str(error)


def test_locked_mechanism_is_a_simulation_error_at_assembly():
    m = pendulum()
    m.add_fixed("weld", "ground.O", "bar.O")
    m.add_driver("motor", "pin", {"kind": "constant_rate", "rate": 2.0})  # turns what the weld holds
    with pytest.raises(jp.SimulationError) as info:
        m.simulate(0.1)
    assert info.value.stage == "assembly" and "locked" in str(info.value)


def test_a_redundant_pin_runs_like_the_single_one_and_shares_its_reaction():
    single = pendulum(angle=0.1)  # off its pin, so assembly iterates on the dependent equations too
    double = pendulum(angle=0.1)
    double.add_revolute("again", "ground.O", "bar.O")
    r1, r2 = single.simulate(0.5, rtol=1e-9, atol=1e-12), double.simulate(0.5, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(r2["bar.angle"][-1], r1["bar.angle"][-1], atol=1e-9)
    pin = next(j["name"] for j in single.to_spec()["joints"])
    # the least-norm multipliers split the one reaction equally between the two coincident pins
    np.testing.assert_allclose(r2[f"{pin}.fy"][-1], 0.5 * r1[f"{pin}.fy"][-1], rtol=1e-6)
    np.testing.assert_allclose(r2["again.fy"][-1], 0.5 * r1[f"{pin}.fy"][-1], rtol=1e-6)
    assert double.check()["redundant_equations"] == 2


def test_ideal_joint_reactions_balance_newtons_law_on_the_slider():
    # the slider is pushed only by the rod through B and guided vertically: m_s a_x = -(force on rod from slider)_x
    results = flores.build_model().idealized().simulate(flores.revolutions_to_time(1.0), rtol=1e-9, atol=1e-12,
                                                        output_step=1e-5)
    np.testing.assert_allclose(0.14 * results["slider.ax"], -results["B.fx"], atol=1e-6 * np.max(np.abs(results["B.fx"])))
    # the work of the motor equals the change of kinetic plus potential energy
    from scipy.integrate import cumulative_trapezoid

    work = cumulative_trapezoid(results["motor.torque"] * results["crank.omega"], results.time, initial=0.0)
    energy = results["system.energy"] - results["system.energy"][0]
    np.testing.assert_allclose(work, energy, atol=1e-4 * np.max(np.abs(energy)))


def test_progress_is_reported():
    seen = []
    pendulum().simulate(0.2, progress=seen.append)
    assert seen and seen[-1] == pytest.approx(0.2)


def test_ctrl_c_stops_a_run_and_keeps_what_was_computed():
    # SIGINT from a timer while the core runs in this (the main) thread: the core lets the
    # signal through at its next call back, stops, and the results up to there are kept
    import os
    import signal
    import threading

    model = flores.build_model()
    t_end = flores.revolutions_to_time(2000.0)  # minutes if it were not interrupted
    # a process started with SIGINT ignored (a background job) would not see the signal: install
    # Python's own handler, as an interactive session has it, for the duration of the test
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(jp.SimulationError) as caught:
            model.simulate(t_end)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    error = caught.value
    assert error.kind == "Interrupted"
    assert 0.0 < error.time < t_end
    assert error.results.time[-1] == pytest.approx(error.time)
    assert np.all(np.isfinite(error.results["B.fn"]))


def test_ctrl_c_stops_a_long_reynolds_solve_from_inside_it():
    # issue 32, item 5: a Reynolds grid within the node limit (480 x 256: 61 920 nodes on the half
    # length) solves in seconds, and a dopri5 step of the lubricated slider-crank takes 8 such solves
    # (measured: 32 s for the first step). Ctrl-C used to wait for the next sample, after that step;
    # now every sweep reaches the check. A callback that interrupts at its first call (about 0.1 s
    # into the run) stops the run inside the first evaluation: at t = 0, with no step taken.
    model = flores.build_model()
    model.joint("B")["lubrication"] = laws.lubrication("reynolds_exact", laws.centipoise(400),
                                                       n_circumferential=480, n_axial=256)
    calls = []

    def interrupt(t):
        calls.append(t)
        raise KeyboardInterrupt

    with pytest.raises(jp.SimulationError) as caught, pytest.warns(jp.JointplayWarning, match="480 x 256"):
        model.simulate(flores.revolutions_to_time(1.0), progress=interrupt)
    assert caught.value.kind == "Interrupted"
    assert calls == [0.0] and caught.value.time == 0.0
    assert caught.value.results.statistics["accepted_steps"] == 0
    assert caught.value.results.statistics["rhs_evaluations"] <= 1


def test_ctrl_c_stops_building_a_force_table():
    # a reynolds_table on a 480 x 64 grid: 2 560 solves of 15 840 nodes, minutes to build when the model
    # is compiled; SIGINT from a timer stops it from inside a solve (as in the test above)
    import os
    import signal
    import threading

    model = flores.build_model()
    model.joint("B")["lubrication"] = laws.lubrication("reynolds_table", laws.centipoise(400),
                                                       n_circumferential=480, n_axial=64)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt, match="compilation interrupted"):
            model.compile()
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)


def test_an_exception_in_the_progress_callback_stops_the_run_and_is_raised():
    calls = []

    def progress(t):
        calls.append(t)
        raise ValueError("stop here")

    model = flores.build_model()
    with pytest.raises(ValueError, match="stop here"):
        model.simulate(flores.revolutions_to_time(2000.0), progress=progress)
    assert len(calls) == 1


def test_builder_round_trips_through_plain_data():
    m = flores.build_model()
    again = jp.Model.from_spec(m.to_spec())
    a = flores.simulate(m, revolutions=0.2)
    b = flores.simulate(again, revolutions=0.2)
    np.testing.assert_array_equal(a["B.fn"], b["B.fn"])


def test_plain_data_missing_a_key_is_a_model_error_naming_the_element_and_the_key():
    # the core's spec has no defaults (the builder sends every key): a description without one is
    # reported by the binding as problems located by element name, not as a crash
    spec = flores.build_model().to_spec()
    del spec["bodies"][0]["angle"]
    del next(j for j in spec["joints"] if j["name"] == "B")["onset_velocity_floor"]
    with pytest.raises(jp.ModelError) as info:
        jp.Model.from_spec(spec).compile()
    assert [(p.location, p.message.partition(" (")[0]) for p in info.value.problems] == [
        ("bodies.crank", "missing field `angle`"), ("joints.B", "missing field `onset_velocity_floor`")]
    assert "no defaults" in info.value.problems[0].message


def test_the_core_reports_a_description_it_cannot_read_as_problems():
    from jointplay import _core

    spec = pendulum().to_spec()
    del spec["forces"]
    assert _core.compile_model(json.dumps(spec))[0] is None
    [(where, message)] = _core.compile_model(json.dumps(spec))[1]
    assert where == "model" and message.startswith("missing field `forces`")
    [(where, message)] = _core.compile_model("{not json")[1]
    assert where == "model" and message.startswith("the model description is not valid JSON")


def test_a_hand_written_lubrication_gets_every_key_from_the_definitions():
    m = flores.build_model()
    joint = next(j for j in m.to_spec()["joints"] if j["name"] == "B")
    joint.update(name="B2", lubrication={"model": "hamrock_short", "viscosity": 0.4})
    keys = {k: v for k, v in joint.items() if k not in ("type", "name", "bearing", "journal")}
    m.add_clearance_revolute("B2", joint["bearing"], joint["journal"], **keys)
    added = next(j for j in m.to_spec()["joints"] if j["name"] == "B2")
    assert added["lubrication"] == laws.lubrication("hamrock_short", 0.4) == {
        "model": "hamrock_short", "viscosity": 0.4, "transition": {"law": "wang_improved", "safe_film_thickness": None},
        "reynolds": {"cavitation": "swift_stieber", "n_circumferential": None, "n_axial": None,
                     "ambient_pressure": 0.0, "groove_supply_pressure": None}}


def test_laws_reach_the_core():
    m = flores.build_model()
    m.joint("B")["contact"] = laws.flores(0.5)
    m.joint("B")["friction"] = laws.coulomb(0.05, velocity_tolerance=1e-3)
    m.joint("B")["stiffness"] = laws.johnson_line()
    results = flores.simulate(m, revolutions=0.3)
    assert results.summary()["clearance_joints"]["B"]["impacts"] >= 1


def test_a_long_simulation_releases_the_gil():
    # while the core runs in another thread, this thread must keep executing Python; with the
    # GIL held it would be frozen for the whole run and count nothing
    import threading

    model = flores.build_model()
    model.joint("B")["lubrication"] = laws.lubrication("reynolds_exact", laws.centipoise(400))
    model.compile()
    done = threading.Event()
    worker = threading.Thread(target=lambda: (flores.simulate(model, revolutions=0.05), done.set()))
    worker.start()
    counted = 0
    while not done.is_set():
        counted += 1
    worker.join()
    assert counted > 10_000


def test_results_keep_the_description_they_ran_and_warnings_come_at_every_run():
    # the description snapshot and its plausibility check are made once per version of the model
    m = pendulum()
    m.add_body("far", mass=1.0, inertia=0.02, position=(50.0, 0))  # a body far from the rest: a warning
    with pytest.warns(jp.JointplayWarning, match="far"):
        first = m.simulate(0.01)
    with pytest.warns(jp.JointplayWarning, match="far"):
        again = m.simulate(0.01)
    m.add_ground_point("P", (1.0, 0))
    with pytest.warns(jp.JointplayWarning, match="far"):
        changed = m.simulate(0.01)
    assert [p["name"] for p in first.spec["ground_points"]] == ["O"]
    assert again.spec is first.spec  # shared, read-only
    assert [p["name"] for p in changed.spec["ground_points"]] == ["O", "P"]
    assert m.to_spec() == changed.spec and m.to_spec() is not changed.spec
