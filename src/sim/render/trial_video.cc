// trial_video.cc: see trial_video.h.
#include "sim/render/trial_video.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <string>

#include "base/input_error.h"
#include "base/units.h"
#include "sim/core/pam_callback.h"
#include "sim/io/outputs.h"

namespace pamsim {
namespace {

constexpr double kPlotWidthShare = 0.32;  // of the frame, each plot
constexpr double kPlotHeightShare = 0.26;
constexpr double kTableLineSpacing = 1.25;  // the overlay table's rows, in font line heights
constexpr int kMinPlotHeightPx = 60;
constexpr double kAngleTickDeg = 10.0;    // the angle plot's range: multiples of this
constexpr double kPressureTickMpa = 0.1;  // the pressure plot's range: [0, a multiple]

// frames at k / fps strictly before the end of the trial: duration x fps when whole
long frames_in(double duration_s, int fps) {
  return static_cast<long>(std::ceil(duration_s * fps - kObservationToleranceS));
}

// libx264's preset: the fast path favours encoding speed, the default path file size
const char* x264_preset_for(RenderQuality quality) {
  return quality == RenderQuality::kFast ? "ultrafast" : "veryfast";
}

void check_frame_side(int side_px, const char* option) {
  if (side_px < kMinFrameSidePx || side_px > kMaxFrameSidePx || side_px % 2 != 0) {
    throw InputError(std::string(option) + " must be an even number of pixels in [" +
                     std::to_string(kMinFrameSidePx) + ", " + std::to_string(kMaxFrameSidePx) +
                     "], got " + std::to_string(side_px));
  }
}

bool ends_with_mp4(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".mp4";
}

// The state's numbers as two text columns, names and values: time, the joint, each
// muscle's chamber pressure and command.
void state_numbers(const TrialSnapshot& snap, std::string* names, std::string* values) {
  const std::vector<std::string>& labels = *snap.labels;
  *names = snap.hinge ? "time\nangle" : "time\nposition";
  char line[96];
  std::snprintf(line, sizeof(line), "%.3f s\n%.2f %s", snap.time_s, snap.joint_position_deg_or_mm,
                snap.hinge ? "deg" : "mm");
  *values = line;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    *names += "\n" + labels[i];
    std::snprintf(line, sizeof(line), "\n%.3f MPa (cmd %.3f)",
                  units::pa_to_mpa((*snap.pressure_pa)[i]),
                  units::pa_to_mpa((*snap.command_pa)[i]));
    *values += line;
  }
}

// Appends (x, y) to a figure line; when the line is full the oldest point goes.
void append_point(mjvFigure* figure, int line, double x, double y) {
  int& n = figure->linepnt[line];
  float* points = figure->linedata[line];
  if (n == mjMAXLINEPNT) {
    std::memmove(points, points + 2, sizeof(float) * 2 * (mjMAXLINEPNT - 1));
    --n;
  }
  points[2 * n] = static_cast<float>(x);
  points[2 * n + 1] = static_cast<float>(y);
  ++n;
}

}  // namespace

std::string figure_time_format(double duration_s, int grid_lines) {
  // the labels' step, and the fewest decimals that write it exactly
  const double step = duration_s / std::max(1, grid_lines - 1);
  for (int decimals = 0; decimals < 3; ++decimals) {
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) {
      return "%." + std::to_string(decimals) + "f";
    }
  }
  return "%.3f";
}

namespace {

// A translucent figure over [0, duration] s with lines of the given colours; the title says
// which line is which (a legend does not fit a plot this small).
void init_figure(mjvFigure* figure, const char* title, const char* y_format, double duration_s,
                 const std::vector<std::array<float, 3>>& line_rgb) {
  mjv_defaultFigure(figure);
  std::snprintf(figure->title, sizeof(figure->title), "%s", title);
  std::snprintf(figure->yformat, sizeof(figure->yformat), "%s", y_format);
  figure->flg_legend = 0;
  figure->range[0][0] = 0.0f;
  figure->range[0][1] = static_cast<float>(duration_s);
  figure->figurergba[3] = 0.6f;
  figure->panergba[3] = 0.6f;
  figure->gridsize[0] = 4;
  std::snprintf(figure->xformat, sizeof(figure->xformat), "%s",
                figure_time_format(duration_s, figure->gridsize[0]).c_str());
  figure->gridsize[1] = 3;
  int i = 0;
  for (const auto& rgb : line_rgb) std::copy(rgb.begin(), rgb.end(), figure->linergb[i++]);
}

// y range [lo, hi] of whole multiples of `tick` around [min, max]
void set_y_range(mjvFigure* figure, double min, double max, double tick) {
  figure->range[1][0] = static_cast<float>(tick * std::floor(min / tick));
  figure->range[1][1] = static_cast<float>(tick * std::ceil(max / tick));
  if (figure->range[1][1] <= figure->range[1][0]) figure->range[1][1] += static_cast<float>(tick);
}

// the muscles whose windows are open, each with its channel's tag ("VAS + SOL Ib"), or "off"
std::string reflex_state(const TrialSnapshot& snap) {
  std::string state;
  for (std::size_t k = 0; snap.channels && k < snap.channels->size(); ++k) {
    const ControllerChannel& channel = (*snap.channels)[k];
    const std::vector<double>& open = (*snap.channel_values)[k];
    for (std::size_t i = 0; channel.window && i < open.size(); ++i) {
      if (open[i] == 0.0) continue;
      state += (state.empty() ? "" : " + ") + (*snap.labels)[i] + channel.window_tag;
    }
  }
  return state.empty() ? "off" : state;
}

// muscle i's line colour in the pressure plot (the arm's agonist red, antagonist blue),
// its command dimmer
// Each muscle's own colour in the live plot, up to eight (a leg's), and its name in the key.
constexpr std::size_t kMuscleColours = 8;
constexpr std::array<float, 3> kMuscleRgb[kMuscleColours] = {
    {0.95f, 0.3f, 0.3f}, {0.35f, 0.45f, 1.0f}, {0.3f, 0.8f, 0.35f}, {0.75f, 0.4f, 0.9f},
    {1.0f, 0.6f, 0.15f}, {0.2f, 0.85f, 0.9f},  {1.0f, 0.5f, 0.8f},  {0.65f, 0.5f, 0.3f}};
constexpr const char* kMuscleColourNames[kMuscleColours] = {"red",    "blue", "green", "purple",
                                                            "orange", "cyan", "pink",  "brown"};

std::array<float, 3> muscle_rgb(std::size_t i, bool command) {
  std::array<float, 3> c = kMuscleRgb[i % kMuscleColours];
  if (command) {
    for (float& v : c) v *= 0.55f;
  }
  return c;
}

}  // namespace

// The live plots: angle above, pressures (chamber and command, both muscles) below, and
// the extremes so far that set their ranges.
struct TrialVideo::Plots {
  mjvFigure angle;
  mjvFigure pressure;
  double angle_min_deg = std::numeric_limits<double>::infinity();
  double angle_max_deg = -std::numeric_limits<double>::infinity();
  double pressure_max_mpa = 0.0;
};

void validate_video_options(const VideoOptions& o, const std::string& mp4_option) {
  check_frame_side(o.width_px, "--width");
  check_frame_side(o.height_px, "--height");
  if (o.fps < 1 || o.fps > kMaxVideoFps) {
    throw InputError("--fps must be in [1, " + std::to_string(kMaxVideoFps) + "], got " +
                     std::to_string(o.fps));
  }
  if (o.mp4_path.empty() && o.png_dir.empty()) {
    throw InputError("nothing to write: give " + mp4_option + " FILE.mp4 or --png-dir DIR");
  }
  if (!o.x264_preset.empty()) {
    std::string names;
    bool known = false;
    for (const char* p : kX264Presets) {
      known = known || o.x264_preset == p;
      names += std::string(names.empty() ? "" : ", ") + p;
    }
    if (!known)
      throw InputError("--preset must be one of " + names + ", got '" + o.x264_preset + "'");
  }
  if (!o.mp4_path.empty() && o.mp4_path != "-") {  // "-": standard output
    if (!ends_with_mp4(o.mp4_path)) {
      throw InputError(mp4_option + " " + o.mp4_path + ": the video is an MP4 file, name it .mp4");
    }
    if (std::filesystem::is_directory(o.mp4_path)) {
      throw InputError(mp4_option + " " + o.mp4_path + ": is a folder, name the .mp4 file");
    }
  }
}

TrialVideo::TrialVideo(const TrialModel& model, const Scenario& sc, const VideoOptions& options,
                       std::uint64_t seed)
    : options_(options),
      title_(std::filesystem::path(sc.path).filename().string() + ", seed " + std::to_string(seed)),
      frame_count_(frames_in(sc.duration_s, options.fps)),
      scene_(model, sc,
             SceneRenderOptions{options.width_px, options.height_px, options.quality,
                                options.camera, options.backend, options.egl_device}),
      renderer_(scene_.renderer()) {
  if (options.plot) {
    plots_ = std::make_unique<Plots>();
    // the muscles in their tendons' colours, commands dimmer
    // the measured joint by name ("knee angle [deg]"): a leg has several
    const std::string joint =
        model.joint.name + (model.joint.hinge ? " angle [deg]" : " position [mm]");
    init_figure(&plots_->angle, joint.c_str(), "%.0f", sc.duration_s,
                {{0.9f, 0.75f, 0.1f}});  // yellow
    std::vector<std::array<float, 3>> lines;
    const std::size_t n = std::min<std::size_t>(model.muscles.size(), mjMAXLINE / 2);
    for (std::size_t i = 0; i < n; ++i) lines.push_back(muscle_rgb(i, false));
    for (std::size_t i = 0; i < n; ++i) lines.push_back(muscle_rgb(i, true));
    lines.push_back({1.0f, 1.0f, 1.0f});  // the reflex trigger, white
    init_figure(&plots_->pressure, "pressure [MPa] (dim: command)", "%.1f", sc.duration_s, lines);
    // one entry per colour: each muscle its own up to eight, more joined ("red IL/X"); three
    // entries a line, so that the key box stays narrow, clear of the numbers' box and of a
    // leg framed in the middle
    constexpr std::size_t kPerLine = 3;
    for (std::size_t c = 0; c < std::min(n, kMuscleColours); ++c) {
      plot_key_ += std::string(c == 0              ? ""
                               : c % kPerLine == 0 ? "\n"
                                                   : ", ") +
                   kMuscleColourNames[c] + " ";
      for (std::size_t i = c; i < n; i += kMuscleColours) {
        plot_key_ += (i > c ? "/" : "") + model.muscles[i].label;
      }
    }
    plots_->angle.linergb[1][0] = plots_->angle.linergb[1][1] = plots_->angle.linergb[1][2] = 1.0f;
  }

  // outputs last: their temp files exist only once everything else is ready
  if (!options.mp4_path.empty()) {
    const std::string folder = std::filesystem::path(options.mp4_path).parent_path().string();
    if (!folder.empty() && options.mp4_path != "-") make_directories(folder);
    Mp4Settings settings;
    settings.width_px = options.width_px;
    settings.height_px = options.height_px;
    settings.fps = options.fps;
    settings.x264_preset =
        options.x264_preset.empty() ? x264_preset_for(options.quality) : options.x264_preset;
    mp4_ = std::make_unique<Mp4Writer>(options.mp4_path, settings);
  }
  if (!options.png_dir.empty()) {
    png_ =
        std::make_unique<PngSequenceWriter>(options.png_dir, options.width_px, options.height_px);
  }
}

TrialVideo::~TrialVideo() = default;

double TrialVideo::next_observation_time_s() const {
  if (next_frame_ >= frame_count_) return std::numeric_limits<double>::infinity();
  return static_cast<double>(next_frame_) / options_.fps;
}

void TrialVideo::observe(const TrialSnapshot& snapshot) {
  scene_.draw(snapshot);
  draw_overlays(snapshot);
  const unsigned char* rgb = renderer_.read_pixels();

  // every frame time up to now shows this state (several only if fps beats the physics rate)
  const double due_s = snapshot.time_s + kObservationToleranceS;
  while (next_frame_ < frame_count_ && static_cast<double>(next_frame_) / options_.fps <= due_s) {
    if (mp4_) mp4_->write_frame(rgb);
    if (png_) png_->write_frame(rgb);
    ++next_frame_;
    if (options_.on_frame) options_.on_frame(next_frame_, frame_count_);
  }
}

void TrialVideo::draw_overlays(const TrialSnapshot& snap) {
  // the numbers, top left: time, the joint, each muscle's chamber pressure and command
  const std::vector<std::string>& labels = *snap.labels;
  std::string names, values;
  state_numbers(snap, &names, &values);
  char line[96];
  // the reflex: which window is open, and when it first triggered
  const std::string state = reflex_state(snap);
  if (std::isfinite(snap.first_trigger_s)) trigger_s_ = snap.first_trigger_s;
  std::string reflex = state;
  if (trigger_s_ >= 0) {
    std::snprintf(line, sizeof(line), "%s (first trigger %.2f s)", state.c_str(), trigger_s_);
    reflex = line;
  }
  renderer_.draw_text((names + "\nreflex").c_str(), (values + "\n" + reflex).c_str());
  // the title and the keys, top right
  std::snprintf(line, sizeof(line), "%s, t = %.2f s\ndark 0 to yellow %.1f MPa", title_.c_str(),
                snap.time_s, units::pa_to_mpa(scene_.colour_max_pa()));
  std::string keys = "trial\nmuscle colour";
  std::string key_values = line;
  if (plots_) {
    keys += "\nplot lines";
    for (char c : plot_key_) keys += c == '\n' ? "\n" : "";  // a continued key's rows
    key_values += "\n" + plot_key_ + "; white: trigger";
  }
  renderer_.draw_text(keys.c_str(), key_values.c_str(), mjGRID_TOPRIGHT);
  scene_.draw_colour_key();  // the muscles' colour scale, drawn
  if (!plots_) return;

  // the live plots, bottom left: pressures at the bottom, the joint above
  Plots& p = *plots_;
  append_point(&p.angle, 0, snap.time_s, snap.joint_position_deg_or_mm);
  p.angle_min_deg = std::min(p.angle_min_deg, snap.joint_position_deg_or_mm);
  p.angle_max_deg = std::max(p.angle_max_deg, snap.joint_position_deg_or_mm);
  const std::size_t n = std::min<std::size_t>(labels.size(), mjMAXLINE / 2);
  for (std::size_t i = 0; i < n; ++i) {
    const double p_mpa = units::pa_to_mpa((*snap.pressure_pa)[i]);
    const double cmd_mpa = units::pa_to_mpa((*snap.command_pa)[i]);
    append_point(&p.pressure, static_cast<int>(i), snap.time_s, p_mpa);
    append_point(&p.pressure, static_cast<int>(n + i), snap.time_s, cmd_mpa);
    p.pressure_max_mpa = std::max({p.pressure_max_mpa, p_mpa, cmd_mpa});
  }
  set_y_range(&p.angle, p.angle_min_deg, p.angle_max_deg, kAngleTickDeg);
  set_y_range(&p.pressure, 0.0, p.pressure_max_mpa, kPressureTickMpa);
  // the first trigger: a white vertical line across each plot
  if (trigger_s_ >= 0) {
    for (auto [figure, line_index] :
         {std::pair{&p.angle, 1}, {&p.pressure, static_cast<int>(2 * n)}}) {
      figure->linepnt[line_index] = 0;
      append_point(figure, line_index, trigger_s_, figure->range[1][0]);
      append_point(figure, line_index, trigger_s_, figure->range[1][1]);
    }
  }
  const int w = static_cast<int>(kPlotWidthShare * renderer_.width_px());
  const int h = plot_height_px(labels.size() + 3);  // time, joint, the muscles, reflex
  renderer_.draw_figure(mjrRect{0, 0, w, h}, &p.pressure);
  renderer_.draw_figure(mjrRect{0, h, w, h}, &p.angle);
}

int TrialVideo::plot_height_px(std::size_t table_rows) const {
  // a share of the frame, less where the table above the two plots is tall (a leg's eight
  // muscles): the plots stay below it
  const int share = static_cast<int>(kPlotHeightShare * renderer_.height_px());
  const int table = static_cast<int>(kTableLineSpacing * static_cast<double>(table_rows + 1) *
                                     renderer_.line_height_px());
  return std::max(kMinPlotHeightPx, std::min(share, (renderer_.height_px() - table) / 2));
}

void TrialVideo::finish() {
  if (mp4_) mp4_->finish();
  if (png_) png_->finish();
}

std::string TrialVideo::encoder_name() const { return mp4_ ? mp4_->encoder_name() : "png"; }

RenderedTrial run_rendered_trial(const TrialModel& model, const Scenario& sc, std::uint64_t seed,
                                 const VideoOptions& options, bool keep_trajectory) {
  TrialVideo video(model, sc, options, seed);
  TrialOptions trial_options;
  trial_options.keep_trajectory = keep_trajectory;
  trial_options.observer = &video;
  RenderedTrial rendered;
  rendered.trial = run_trial(model, sc, seed, trial_options);
  video.finish();
  rendered.frames = video.frames_written();
  rendered.encoder = video.encoder_name();
  rendered.gl = video.gl_in_use();
  return rendered;
}

}  // namespace pamsim
