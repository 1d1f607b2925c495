/* example_loop.c: the exported controller on a board, one control tick per timer period.
 * The board's side is five hooks, which the lab writes for its hardware (board.c):
 *   board_wait_for_tick()      blocks until the periodic timer fires (control_period_s)
 *   board_read_sensors(...)    each muscle's pressure sensor and gauge amplifier in volts,
 *                              and the fiber sensor's rate in m/s (0 where none is fitted)
 *   board_goal_pressures(...)  the top controller's goal pressure of each muscle [Pa]
 *   board_reflexes_enabled()   false while the experiment switches the reflexes off
 *   board_write_valves(...)    each muscle's valve command [Pa gauge]
 * The state lives in static storage here (the library itself keeps none); a board with an
 * RTOS may keep it in its task instead. The loop never returns. */
#include "pamctl.h"
#include "pamctl_export.h"

void board_wait_for_tick(void);
void board_read_sensors(pamctl_real* pressure_v, pamctl_real* gauge_v, pamctl_real* fiber_rate_m_s);
void board_goal_pressures(pamctl_real time_s, pamctl_real* p_tp_pa);
bool board_reflexes_enabled(void);
void board_write_valves(const pamctl_real* p_cmd_pa);

static pamctl_config config;
static pamctl_state state;
static pamctl_input input;
static pamctl_output output;

/* Runs the controller; returns only when the configuration is refused (its code, with
 * every valve vented). */
int32_t pamctl_example_main(void) {
  /* the configuration pamsim exported, checked once */
  pamctl_export_config(&config);
  const int32_t code = pamctl_init(&config, &state);
  if (code != 0) {
    pamctl_tick(&config, &state, &input, &output); /* unconfigured: vents */
    board_write_valves(output.p_cmd_pa);
    return code;
  }
  /* one tick per timer period: read, estimate, reflexes, command */
  for (uint32_t tick = 0;; ++tick) {
    board_wait_for_tick();
    input.time_s = (pamctl_real)tick * config.control_period_s;
    input.enabled = board_reflexes_enabled();
    board_read_sensors(input.pressure_v, input.gauge_v, input.fiber_rate_m_s);
    board_goal_pressures(input.time_s, input.p_tp_pa);
    pamctl_tick(&config, &state, &input, &output);
    board_write_valves(output.p_cmd_pa);
  }
}
