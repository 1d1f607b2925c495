// live_figures.cc: see live_figures.h. Lines per figure: the joint, one; the pressures, two
// per muscle (command dashed as a paler colour, chamber full); the velocities, one per
// muscle and the threshold; the windows, one per muscle and channel.
#include "sim/view/live_figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "base/units.h"

namespace pamsim {
namespace {

enum Figure { kJoint = 0, kPressure = 1, kVelocity = 2, kWindows = 3 };

// the muscles' colours, as the video's plots: red, blue, then more
constexpr float kColours[][3] = {
    {0.95f, 0.30f, 0.25f}, {0.30f, 0.55f, 1.0f},  {0.35f, 0.85f, 0.35f}, {0.95f, 0.80f, 0.25f},
    {0.80f, 0.45f, 0.95f}, {0.30f, 0.85f, 0.85f}, {0.95f, 0.55f, 0.20f}, {0.85f, 0.85f, 0.85f}};

void set_line(mjvFigure* f, int line, const std::string& name, const float rgb[3], float pale) {
  std::snprintf(f->linename[line], sizeof(f->linename[line]), "%s", name.c_str());
  for (int c = 0; c < 3; ++c) f->linergb[line][c] = rgb[c] * pale + (1 - pale) * 0.55f;
}

void set_title(mjvFigure* f, const char* title) {
  std::snprintf(f->title, sizeof(f->title), "%s", title);
  std::snprintf(f->yformat, sizeof(f->yformat), "%s", "%.2g");
  std::snprintf(f->xlabel, sizeof(f->xlabel), "%s", "t [s]");
}

}  // namespace

LiveFigures::LiveFigures(const std::vector<std::string>& labels, bool hinge)
    : muscles_(std::min<std::size_t>(labels.size(), 8)), hinge_(hinge) {
  for (mjvFigure& f : figures_) {
    mjv_defaultFigure(&f);
    f.flg_extend = 1;
    f.gridsize[0] = 5;
    f.gridsize[1] = 4;
    f.figurergba[3] = 0.6f;
    f.legendrgba[3] = 0.0f;
    std::snprintf(f.xformat, sizeof(f.xformat), "%s", "%.1f");
  }
  set_title(&figures_[kJoint], hinge ? "angle [deg]" : "position [mm]");
  set_title(&figures_[kPressure], "pressure [MPa], pale: command");
  set_title(&figures_[kVelocity], "stretch velocity [mm/s]");
  set_title(&figures_[kWindows], "reflex windows");
  const float white[3] = {1, 1, 1};
  set_line(&figures_[kJoint], 0, hinge ? "angle" : "position", white, 1.0f);
  for (std::size_t m = 0; m < muscles_; ++m) {
    const int i = static_cast<int>(m);
    set_line(&figures_[kPressure], 2 * i, labels[m] + " cmd", kColours[m], 0.45f);
    set_line(&figures_[kPressure], 2 * i + 1, labels[m], kColours[m], 1.0f);
    set_line(&figures_[kVelocity], i, labels[m], kColours[m], 1.0f);
    set_line(&figures_[kWindows], i, labels[m], kColours[m], 1.0f);
  }
  set_line(&figures_[kVelocity], static_cast<int>(muscles_), "threshold", white, 0.8f);
  figures_[kWindows].range[1][0] = 0;  // y: 0 (closed) to 1 (open); x as the others
  figures_[kWindows].range[1][1] = 1.2f;
}

void LiveFigures::clear() {
  for (mjvFigure& f : figures_) std::fill(std::begin(f.linepnt), std::end(f.linepnt), 0);
}

void LiveFigures::push(int figure, int line, float x, float y) {
  mjvFigure& f = figures_[figure];
  int& n = f.linepnt[line];
  if (n == mjMAXLINEPNT) {  // the oldest point goes
    std::memmove(f.linedata[line], f.linedata[line] + 2, sizeof(float) * 2 * (mjMAXLINEPNT - 1));
    --n;
  }
  f.linedata[line][2 * n] = x;
  f.linedata[line][2 * n + 1] = y;
  ++n;
}

void LiveFigures::add(const TrialObservation& o, double threshold_mm_s) {
  const float t = static_cast<float>(o.time_s);
  const double q = o.joint_position_rad_or_m;
  push(kJoint, 0, t, static_cast<float>(hinge_ ? units::rad_to_deg(q) : q * 1000.0));
  for (std::size_t m = 0; m < muscles_ && m < o.pressure_pa.size(); ++m) {
    const int i = static_cast<int>(m);
    push(kPressure, 2 * i, t, static_cast<float>(units::pa_to_mpa(o.command_pa[m])));
    push(kPressure, 2 * i + 1, t, static_cast<float>(units::pa_to_mpa(o.pressure_pa[m])));
    push(kVelocity, i, t, static_cast<float>(o.velocity_est_m_s[m] * 1000.0));
    const double open = o.channels.empty() ? 0.0 : o.channels.front()[m];
    push(kWindows, i, t, static_cast<float>(open * (1.0 - 0.05 * i)));
  }
  if (!std::isnan(threshold_mm_s)) {
    push(kVelocity, static_cast<int>(muscles_), t, static_cast<float>(threshold_mm_s));
  }
}

void LiveFigures::draw(const mjrRect& strip, const mjrContext* context) {
  for (int k = 0; k < kFigures; ++k) {
    const int left = strip.left + strip.width * k / kFigures;
    const mjrRect r{left, strip.bottom, strip.left + strip.width * (k + 1) / kFigures - left,
                    strip.height};
    mjr_figure(r, &figures_[k], context);
  }
}

}  // namespace pamsim
