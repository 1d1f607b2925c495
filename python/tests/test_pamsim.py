"""The Python module as a notebook user calls it: laws and their inversion over arrays,
fitting, a run equal to the command line's byte for byte, a stepped Trial equal to a run,
sweep databases, and bad input raising ValueError with pamsim's message.

Run by CTest (make test) with PYTHONPATH=<build>/python, PAMSIM_BINARY and PAMSIM_SOURCE_DIR.
"""

import json
import os
import subprocess
import threading

import numpy as np
import pytest

import pamsim

SOURCE = os.environ["PAMSIM_SOURCE_DIR"]
BINARY = os.environ["PAMSIM_BINARY"]
AGONIST = os.path.join(SOURCE, "models/pams/table4_agonist.toml")
DROP = os.path.join(SOURCE, "scenarios/drop_mass.toml")
SHORT = ["sim.duration_s=1.5", "drop.time_s=0.3"]


def cli(*args, cwd=SOURCE):
    return subprocess.run([BINARY, *args], cwd=cwd, capture_output=True, text=True, check=True)


def test_law_and_its_inversion_round_trip_over_arrays():
    law = pamsim.SpringModel.from_file(AGONIST)
    p, d = np.meshgrid(np.linspace(0.1, 0.8, 50), np.linspace(0.5, 25.0, 60))
    f = law.force_N(p, d)
    assert f.shape == p.shape
    back = law.deformation_mm(p, f)
    status = law.inversion_status(p, f)
    ok = status == 0
    assert ok.mean() > 0.9
    np.testing.assert_allclose(back[ok], d[ok], rtol=0, atol=1e-9)
    # vectorised values are the scalar ones, bit for bit
    assert law.force_N(float(p[3, 7]), float(d[3, 7])) == f[3, 7]
    # Table IV agonist at 0.4 MPa and 10 mm (the estimate example of docs/command-line.md)
    assert law.force_N(0.4, 10.0) == pytest.approx(54.67, abs=1e-9)
    assert law.force_N(0.4, -1.0) == 0.0  # slack
    assert law.natural_length_mm(0.0) == pytest.approx(170.1)


def test_a_noise_free_tensile_test_fits_back_to_its_law():
    law = pamsim.SpringModel.from_file(AGONIST)
    data = pamsim.tensile_test(law, pressures_MPa=[0.3, 0.5, 0.7], step_mm=1.0)
    fit = pamsim.fit(
        "eq3", data["pressure_MPa"], data["deformation_mm"], data["force_N"], data["length_mm"]
    )
    assert fit["r2"] == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(fit["model"].coefficients, law.coefficients, rtol=1e-9)
    assert fit["model"].m_mm_per_MPa == pytest.approx(law.m_mm_per_MPa, rel=1e-9)


def test_fit_from_a_csv_equals_the_command_line(tmp_path):
    csv = tmp_path / "a.csv"
    cli("tensile", "--plant", "models/pams/plant_pam_a.toml", "-o", str(csv))
    mine = pamsim.fit_csv("eq3", str(csv))
    theirs = json.loads(cli("fit", "--model", "eq3", str(csv), "--json").stdout)
    assert mine["points"] == len(pamsim.read_tensile_csv(str(csv))["force_N"])
    assert mine["rmse_N"] == pytest.approx(theirs["rmse_N"], rel=1e-12)


def test_run_equals_the_command_lines_trajectory_byte_for_byte(tmp_path):
    args = []
    for o in SHORT:
        args += ["--set", o]
    cli("run", DROP, *args, "--out", str(tmp_path / "cli"))
    result = pamsim.run(DROP, SHORT)
    assert result.to_csv() == (tmp_path / "cli" / "trajectory.csv").read_text()
    summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert result.summary["status"] == "ok"
    assert result.summary["metrics"]["peak_drop_deg"] == summary["peak_drop_deg"]
    # summary is summary.json's object (the file's path aside), plus "metrics"
    mine = dict(result.summary)
    del mine["metrics"]
    del mine["scenario"]["file"], summary["scenario"]["file"]
    assert mine == summary
    # overrides as a dict are the same thing
    same = pamsim.run(DROP, {"sim.duration_s": 1.5, "drop.time_s": 0.3})
    assert np.array_equal(same.values, result.values)
    traj = pamsim.trajectory(result)
    assert traj["time_s"][0] == 0.0 and len(traj["angle_deg"]) == result.values.shape[0]


def test_a_stepped_trial_with_the_reflex_controller_reproduces_run():
    ran = pamsim.run(DROP, SHORT, seed=3)
    trial = pamsim.Trial(DROP, SHORT, seed=3)
    periods = 0
    while trial.step():
        periods += 1
    assert trial.done
    stepped = trial.finish()
    assert periods + 1 == ran.values.shape[0]
    assert stepped.columns == ran.columns
    assert np.array_equal(stepped.values, ran.values)
    assert stepped.summary["metrics"]["peak_drop_deg"] == ran.summary["metrics"]["peak_drop_deg"]


def test_a_python_controller_drives_the_valves():
    trial = pamsim.Trial(DROP, ["sim.duration_s=0.3", "drop.time_s=0.1"])
    assert len(trial.muscles) == 2
    obs = trial.observe()
    assert set(obs) >= {
        "time_s",
        "angle_deg",
        "pressure_MPa",
        "command_MPa",
        "force_N",
        "length_mm",
        "length_est_mm",
        "reflex_active",
    }
    # a proportional controller on the angle, in Python
    while trial.step(np.array([0.45, 0.45]) + 0.001 * np.array([1, -1]) * obs["angle_deg"]):
        obs = trial.observe()
        assert obs["command_MPa"] == pytest.approx(
            np.array([0.45, 0.45]) + 0.001 * np.array([1, -1]) * obs["angle_deg"], abs=0.01
        )
    result = trial.finish()
    assert result.summary["status"] == "ok"


def test_the_observation_names_every_channel_of_the_table_in_its_unit():
    """observe() carries each row of trajectory.csv's channel table by its name without the
    muscle, one value per muscle, in the log's units."""
    trial = pamsim.Trial(DROP, ["sim.duration_s=0.3", "drop.time_s=0.1"])
    trial.step()
    obs = trial.observe()
    rows = [r for r in pamsim.channels() if r["per_muscle"] and r["name"] != "{controller}"]
    assert {r["quantity"] for r in rows} >= {"p_meas_MPa", "force_N", "length_est_mm"}
    for r in rows:
        assert len(obs[r["quantity"]]) == len(trial.muscles), r["name"]
    for r in (r for r in rows if r["measured"]):
        assert r["quantity"] in obs["measured"], r["name"]
    # MPa is the chamber's Pa / 1e6, as trajectory.csv has it
    p = obs["p_MPa"]
    assert np.array_equal(obs["pressure_MPa"], p)
    assert all(0.0 <= v < 1.0 for v in p)


def test_bad_input_raises_value_error_with_the_message():
    with pytest.raises(ValueError, match="scenarios/missing.toml"):
        pamsim.run(os.path.join(SOURCE, "scenarios/missing.toml"))
    with pytest.raises(pamsim.InputError, match="sim.duration_s"):
        pamsim.run(DROP, {"sim.duration_s": -1.0})
    with pytest.raises(ValueError, match="law"):
        pamsim.SpringModel("eq9", 1.0, 2.0, [1.0])
    with pytest.raises(ValueError, match="takes 4 coefficients"):
        pamsim.SpringModel("eq3", 1.0, 2.0, [1.0])
    with pytest.raises(ValueError, match="same length"):
        pamsim.fit("eq3", [0.4, 0.5], [1.0], [2.0, 3.0])
    with pytest.raises(ValueError, match="law_or_plant"):
        pamsim.tensile_test(3.0)
    with pytest.raises(ValueError, match="step_mm"):
        pamsim.tensile_test(pamsim.SpringModel.from_file(AGONIST), step_mm=0.0)
    trial = pamsim.Trial(DROP, SHORT)
    with pytest.raises(ValueError, match="3 values for 2 muscles"):
        trial.step([0.4, 0.4, 0.4])
    with pytest.raises(ValueError, match="finite"):
        trial.step([0.4, float("nan")])
    with pytest.raises(ValueError, match="no such sweep database"):
        pamsim.read_sweep("/nonexistent.db")


def test_sweep_databases_read_as_the_export(tmp_path):
    db = tmp_path / "smoke.db"
    cli("sweep", "scenarios/sweep_smoke.toml", "--db", str(db))
    cols = pamsim.read_sweep(str(db))
    assert len(cols["trial"]) == 32
    assert list(cols["status"]) == ["ok"] * 32
    csv = tmp_path / "smoke.csv"
    cli("export", str(db), "--csv", str(csv))
    header = csv.read_text().splitlines()[0].split(",")
    assert set(header) <= set(cols)
    exported = np.genfromtxt(csv, delimiter=",", names=True, dtype=None, encoding=None)
    np.testing.assert_array_equal(cols["peak_drop_deg"], exported["peak_drop_deg"])


def test_trials_release_the_gil():
    # a Python thread keeps running while trials run in another
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    try:
        for _ in range(3):
            pamsim.run(DROP, SHORT)
    finally:
        done.set()
        counter.join()
    assert len(ticks) > 20


def test_pandas_frames_when_pandas_is_there():
    pandas = pytest.importorskip("pandas")
    frame = pamsim.frame(pamsim.run(DROP, ["sim.duration_s=0.4", "drop.time_s=0.1"]))
    assert isinstance(frame, pandas.DataFrame) and "angle_deg" in frame.columns


def test_tuning_databases_read_evaluation_by_evaluation(tmp_path):
    tune = tmp_path / "bias.toml"
    tune.write_text(
        f'base = "{SOURCE}/scenarios/drop_mass_ideal.toml"\n'
        'overrides = ["sim.duration_s=0.6", "drop.time_s=0.3", "drop.enabled=false", '
        '"reflex.enabled=false"]\n'
        'algorithm = "cmaes"\ngenerations = 2\npopulation = 5\nseed = 3\nseeds = 1\n'
        "noise_scales = [0.0]\nheld_out_seeds = 0\n"
        '[[parameter]]\nkey = "sensors.pressure_bias_MPa"\nfrom = -0.05\nto = 0.03\n'
        '[[objective]]\nmetric = "length_est_rmse_pct"\n'
    )
    cli("tune", str(tune), "--out", str(tmp_path / "out"), "--db", str(tmp_path / "tune.db"))
    evaluations = pamsim.read_tune(str(tmp_path / "tune.db"))
    assert [e["evaluation"] for e in evaluations] == list(range(len(evaluations)))
    assert len(evaluations) >= 10
    assert all(-0.05 <= e["values"][0] <= 0.03 and len(e["objectives"]) == 1 for e in evaluations)
    with pytest.raises(ValueError, match="tuning database"):
        pamsim.read_tune(str(tmp_path / "absent.db"))
