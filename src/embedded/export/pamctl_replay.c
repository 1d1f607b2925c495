/* pamctl_replay.c: the exported controller on a host, fed a trial's readings.csv (written by
 * `pamsim run --readings`: the controller's inputs exactly as pamsim handed them):
 *   pamctl_replay readings.csv [out.csv]
 * writes per tick the commands [Pa], each muscle's velocity and reflex windows, and the
 * status to out.csv (standard output by default), and compares the commands with the file's
 * p_cmd_<m>_Pa columns: one line on standard error, "ticks N, commands equal" or "ticks N,
 * first differing tick K, largest difference D Pa", exit status 0 when equal, 1 when not, 2
 * for a file it cannot read. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pamctl.h"
#include "pamctl_export.h"

#define LINE_MAX_BYTES 65536
#define COLUMNS_MAX 256

/* the index of `name` among the header's cells, or -1 */
static int find_column(char cells[][96], int count, const char* name) {
  for (int k = 0; k < count; ++k) {
    if (strcmp(cells[k], name) == 0) return k;
  }
  return -1;
}

/* `line` split at commas into cells (each at most 95 bytes); returns the count */
static int split(char* line, char cells[][96], int max) {
  int count = 0;
  for (char* cell = strtok(line, ",\r\n"); cell && count < max; cell = strtok(NULL, ",\r\n")) {
    strncpy(cells[count], cell, 95);
    cells[count++][95] = '\0';
  }
  return count;
}

/* the columns of one muscle: pressure, gauge, fiber, goal, command */
typedef struct {
  int at[5];
} muscle_columns;

static int header_columns(char cells[][96], int count, int* time_at, int* enabled_at,
                          muscle_columns* muscles) {
  static const char* const names[] = PAMCTL_EXPORT_MUSCLE_NAMES;
  static const char* const forms[5] = {"pressure_sensor_%s_V", "gauge_%s_V", "fiber_rate_%s_m_s",
                                       "p_tp_%s_Pa", "p_cmd_%s_Pa"};
  *time_at = find_column(cells, count, "time_s");
  *enabled_at = find_column(cells, count, "enabled");
  if (*time_at < 0 || *enabled_at < 0) return -1;
  for (int j = 0; j < PAMCTL_EXPORT_MUSCLE_COUNT; ++j) {
    for (int q = 0; q < 5; ++q) {
      char name[128];
      snprintf(name, sizeof(name), forms[q], names[j]);
      muscles[j].at[q] = find_column(cells, count, name);
      if (muscles[j].at[q] < 0) {
        fprintf(stderr, "pamctl_replay: no column %s\n", name);
        return -1;
      }
    }
  }
  return 0;
}

/* one row of out.csv */
static void write_row(FILE* out, long tick, double time_s, const pamctl_output* o, int n) {
  fprintf(out, "%ld,%.17g", tick, time_s);
  for (int j = 0; j < n; ++j) fprintf(out, ",%.17g", (double)o->p_cmd_pa[j]);
  for (int j = 0; j < n; ++j) fprintf(out, ",%.17g", (double)o->velocity_m_s[j]);
  for (int j = 0; j < n; ++j) fprintf(out, ",%d,%d", o->ia_active[j], o->ia_triggered[j]);
  for (int j = 0; j < n; ++j) fprintf(out, ",%d,%d", o->ib_active[j], o->ib_triggered[j]);
  fprintf(out, ",%u\n", (unsigned)o->status);
}

static void write_header(FILE* out, int n) {
  static const char* const names[] = PAMCTL_EXPORT_MUSCLE_NAMES;
  fprintf(out, "tick,time_s");
  for (int j = 0; j < n; ++j) fprintf(out, ",p_cmd_%s_Pa", names[j]);
  for (int j = 0; j < n; ++j) fprintf(out, ",velocity_%s_m_s", names[j]);
  for (int j = 0; j < n; ++j) fprintf(out, ",reflex_%s,trigger_%s", names[j], names[j]);
  for (int j = 0; j < n; ++j)
    fprintf(out, ",tension_reflex_%s,tension_trigger_%s", names[j], names[j]);
  fprintf(out, ",status\n");
}

/* the commands against the file's p_cmd_<m>_Pa at one tick */
static void compare_row(char cells[][96], const muscle_columns* muscles, const pamctl_output* o,
                        long tick, long* first_differing, double* largest) {
  for (int j = 0; j < PAMCTL_EXPORT_MUSCLE_COUNT; ++j) {
    const double logged = strtod(cells[muscles[j].at[4]], NULL);
    const double diff = fabs((double)o->p_cmd_pa[j] - logged);
    if (diff != 0.0 && *first_differing < 0) *first_differing = tick;
    if (diff > *largest) *largest = diff;
  }
}

static pamctl_config config;
static pamctl_state state;
static pamctl_input input;
static pamctl_output output;
static char line[LINE_MAX_BYTES];
static char cells[COLUMNS_MAX][96];

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: pamctl_replay readings.csv [out.csv]\n");
    return 2;
  }
  FILE* in = fopen(argv[1], "r");
  FILE* out = argc > 2 ? fopen(argv[2], "w") : stdout;
  if (!in || !out) {
    fprintf(stderr, "pamctl_replay: cannot open %s\n", !in ? argv[1] : argv[2]);
    return 2;
  }
  pamctl_export_config(&config);
  const int32_t code = pamctl_init(&config, &state);
  if (code != 0) {
    fprintf(stderr, "pamctl_replay: configuration refused: %s\n", pamctl_config_error(code));
    return 2;
  }
  /* the header's columns */
  int time_at = -1, enabled_at = -1;
  muscle_columns muscles[PAMCTL_EXPORT_MUSCLE_COUNT];
  if (!fgets(line, sizeof(line), in) ||
      header_columns(cells, split(line, cells, COLUMNS_MAX), &time_at, &enabled_at, muscles)) {
    fprintf(stderr, "pamctl_replay: %s: not a readings.csv of this export's muscles\n", argv[1]);
    return 2;
  }
  const int n = PAMCTL_EXPORT_MUSCLE_COUNT;
  write_header(out, n);
  /* every tick: the inputs, the controller, the commands against the file's */
  long tick = 0, first_differing = -1;
  double largest = 0.0;
  for (; fgets(line, sizeof(line), in); ++tick) {
    const int count = split(line, cells, COLUMNS_MAX);
    if (count <= time_at || count <= enabled_at) break;
    const double time_s = strtod(cells[time_at], NULL);
    input.time_s = (pamctl_real)time_s;
    input.enabled = strtod(cells[enabled_at], NULL) != 0.0;
    for (int j = 0; j < n; ++j) {
      input.pressure_v[j] = (pamctl_real)strtod(cells[muscles[j].at[0]], NULL);
      input.gauge_v[j] = (pamctl_real)strtod(cells[muscles[j].at[1]], NULL);
      input.fiber_rate_m_s[j] = (pamctl_real)strtod(cells[muscles[j].at[2]], NULL);
      input.p_tp_pa[j] = (pamctl_real)strtod(cells[muscles[j].at[3]], NULL);
    }
    pamctl_tick(&config, &state, &input, &output);
    write_row(out, tick, time_s, &output, n);
    compare_row(cells, muscles, &output, tick, &first_differing, &largest);
  }
  if (out != stdout) fclose(out);
  fclose(in);
  if (first_differing < 0) {
    fprintf(stderr, "ticks %ld, commands equal\n", tick);
    return 0;
  }
  fprintf(stderr, "ticks %ld, first differing tick %ld, largest difference %.17g Pa\n", tick,
          first_differing, largest);
  return 1;
}
