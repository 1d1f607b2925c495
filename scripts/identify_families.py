"""identify_families.py: the families of synthetic arms scripts/identify_coverage.py
identifies, as data. A family names the parameters whose truth is drawn (the range each is
drawn from, the range identified, the scale), the instruments' zero errors (drawn, and the
range fitted), the recordings (their conditions as scenario overrides, the channels a lab's
logger keeps, its rate, whether the fit sees them) and the search settings its identification
files give (none: the file's defaults).

  example  the worked example's arm (docs/identification.md): both bladder walls, the
           shoulder's damping, the regulator's dead time (the 2-10 ms bracket of
           models/pams/pneumatics.toml), three zero errors; an agonist step schedule and an
           antagonist sine fitted, the reaching ramps held out (make_recordings.py's).
  harder   what a lab fitting its friction and its regulator would ask: the antagonist's wall,
           the agonist's extension friction A0 (models/pams/plant_agonist.toml: 2.36 mm^2, an
           assumption sized from Wickramatunge and Leephakpreeda), the main valve's time
           constant and the regulator's proportional band (pneumatics.toml's 5-20 ms bracket
           and 380 kPa), four zero errors; the ball dropped on the passive arm and a heavier
           ball dropped, fitted, and the ball dropped under the stretch reflex, held out.
"""

import os
import sys

sys.path.insert(
    0,
    os.path.join(
        os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples", "identify"
    ),
)
import make_recordings  # noqa: E402  (the example's logger)

# the ball released at 1 s, the trial 3 s long: a drop's conditions
DROP = [
    "sim.duration_s=3",
    'events.fall.action="release"',
    'events.fall.body="ball"',
    "events.fall.when.at_s=1.0",
]
DROP_CHANNELS = ["angle_deg", "p_meas_ago_MPa", "force_meas_ago_N", "force_meas_anta_N"]

FAMILIES = {
    "example": {
        # key: (truth drawn from [lo, hi], the identification's range [from, to], scale)
        "truth": {
            "muscles.antagonist.plant.geometry.wall_thickness_mm": (
                (2.5, 3.3),
                (2.0, 4.0),
                "linear",
            ),
            "muscles.agonist.plant.geometry.wall_thickness_mm": ((1.8, 2.5), (1.5, 3.0), "linear"),
            "joints.shoulder.damping_N_m_s_per_rad": ((0.06, 0.3), (0.02, 0.5), "log"),
            "valve.dead_time_ms": ((2.0, 10.0), (0.5, 20.0), "linear"),
        },
        # channel: (zero error drawn from [lo, hi] in the column's unit, the range fitted)
        "offsets": {
            "angle_deg": ((-0.5, 0.5), (-2.0, 2.0)),
            "p_meas_ago_MPa": ((-0.01, 0.01), (-0.03, 0.03)),
            "force_meas_anta_N": ((-2.0, 2.0), (-5.0, 5.0)),
        },
        # name: (conditions, channels, rate [Hz], held out)
        "recordings": {
            "steps": (
                make_recordings.RECORDINGS["steps"][0],
                ["angle_deg", "p_meas_ago_MPa", "force_meas_anta_N"],
                50.0,
                False,
            ),
            "sine": (
                make_recordings.RECORDINGS["sine"][0],
                ["angle_deg", "force_meas_anta_N"],
                40.0,
                False,
            ),
            "ramps": (make_recordings.RECORDINGS["ramps"][0], ["angle_deg"], 25.0, True),
        },
        # one run of 8 generations of 12 (the search this family's coverage was first measured
        # at, before the default became three runs)
        "search": {
            "generations": 8,
            "population": 12,
            "polish_iterations": 30,
            "runs": 1,
            "stall_generations": 0,
        },
    },
    "harder": {
        "truth": {
            "muscles.antagonist.plant.geometry.wall_thickness_mm": (
                (2.5, 3.3),
                (2.0, 4.0),
                "linear",
            ),
            "muscles.agonist.plant.friction.extension.A0_mm2": ((1.2, 4.0), (0.5, 8.0), "log"),
            "valve.valve_time_constant_ms": ((8.0, 30.0), (4.0, 60.0), "log"),
            "valve.proportional_band_kPa": ((300.0, 550.0), (200.0, 800.0), "log"),
        },
        "offsets": {
            "angle_deg": ((-0.5, 0.5), (-2.0, 2.0)),
            "p_meas_ago_MPa": ((-0.01, 0.01), (-0.03, 0.03)),
            "force_meas_ago_N": ((-2.0, 2.0), (-5.0, 5.0)),
            "force_meas_anta_N": ((-2.0, 2.0), (-5.0, 5.0)),
        },
        "recordings": {
            "passive_drop": (DROP, DROP_CHANNELS, 50.0, False),
            "heavy_drop": (DROP + ["bodies.ball.mass_kg=0.5"], DROP_CHANNELS, 50.0, False),
            "reflex_drop": (DROP + ['controller.kind="stretch_reflex"'], ["angle_deg"], 50.0, True),
        },
        "search": {},
    },
}
