// identify_plot.cc: recording_<name>.png of identify_outputs.h: a recording's channels, one
// panel each, recorded (points) against the simulation before (the base scenario, dashed)
// and after identification (line); with no parameter fitted, the model's one line.
#include <cmath>
#include <sstream>

#include "base/format.h"
#include "sim/io/gnuplot.h"
#include "sim/optimize/identify_outputs.h"

namespace pamsim {
namespace {

std::string value_text(const std::vector<double>& v, std::size_t k) {
  return k < v.size() && std::isfinite(v[k]) ? format_shortest(v[k]) : "NaN";
}

}  // namespace

void write_recording_plot(const std::string& png_path, const IdentifyRecording& recording,
                          const std::vector<const ChannelFit*>& fits, bool fitted) {
  GnuplotJob job;
  job.width_px = 1200;
  job.height_px = 300 + 280 * static_cast<int>(fits.size());
  std::ostringstream data, script;
  for (std::size_t k = 0; k < recording.data.time_s.size(); ++k) {
    data << format_shortest(recording.data.time_s[k]);
    for (std::size_t i = 0; i < fits.size(); ++i) {
      const std::vector<double>& rec = recording.data.samples[recording.channels[i]];
      data << ' ' << value_text(rec, k) << ' ' << value_text(fits[i]->before, k) << ' '
           << value_text(fits[i]->after, k);
    }
    data << '\n';
  }
  job.data_files.emplace_back("recording.dat", data.str());
  script << "set multiplot layout " << fits.size() << ",1 title "
         << gp_quote("recording " + recording.name + (recording.held_out ? " (held out)" : "") +
                     (fitted ? ": recorded, before and after identification"
                             : ": recorded and the model"))
         << "\nset grid\nset key outside right\nset datafile missing 'NaN'\n";
  for (std::size_t i = 0; i < fits.size(); ++i) {
    const std::size_t col = 2 + 3 * i;
    script << "set ylabel " << gp_quote(fits[i]->channel) << "\n"
           << (i + 1 == fits.size() ? "set xlabel 'time [s]'\n" : "unset xlabel\n")
           << "plot 'recording.dat' using 1:" << col
           << " with points pt 7 ps 0.4 lc rgb '#444444' title 'recorded', ";
    if (fitted) {
      script << "'' using 1:" << col + 1
             << " with lines dt 2 lw 1.5 lc rgb '#c0392b' title 'before', ";
    }
    script << "'' using 1:" << col + 2 << " with lines lw 1.5 lc rgb '#2166ac' title "
           << (fitted ? "'after'" : "'model'") << "\n";
  }
  script << "unset multiplot\n";
  job.script = script.str();
  run_gnuplot(png_path, job);
}

}  // namespace pamsim
