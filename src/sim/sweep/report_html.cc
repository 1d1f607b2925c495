// report_html.cc: see report_html.h.
#include "sim/sweep/report_html.h"

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/format.h"

namespace pamsim {
namespace {

// The page's script: a hovered cell's points described in the tooltip, a replayed point's trials
// opened by a click on its cell or its row's link.
constexpr const char* kScript = R"JS(
const data = JSON.parse(document.getElementById('page-data').textContent);
const tip = document.getElementById('tip');
function fmt(v) { return v === null ? 'n/a' : Number(v.toPrecision(4)).toString(); }
function pointsOf(el) {
  const map = data.maps[el.dataset.map];
  if (!map) return [];
  if (el.dataset.i !== undefined) return [map.points[Number(el.dataset.i)]];
  return map.cells[el.dataset.ix + ',' + el.dataset.iy] || [];
}
function line(parent, text, tag) {
  const e = document.createElement(tag || 'div');
  e.textContent = text;
  parent.appendChild(e);
}
function describe(i) {
  const p = data.points[i], box = document.createElement('div');
  line(box, 'point ' + p.point + ': ' + data.axes.map((a, k) => a + ' = ' + p.axes[k]).join(', '), 'b');
  line(box, p.ok + ' of ' + p.trials + ' trials ok; mistrip rate ' + fmt(p.mistrip_rate));
  data.metrics.forEach((m, k) => {
    const v = p.metrics[k];
    line(box, m + ': ' + fmt(v[0]) + ' \u00b1 ' + fmt(v[1]) + ' [' + fmt(v[2]) + ', ' + fmt(v[3]) + '], n ' + v[4]);
  });
  line(box, p.replayed ? 'its trials: click the cell' : p.replay, p.replayed ? 'i' : 'code');
  return box;
}
function openPoint(point) {
  const d = document.getElementById('point-' + point);
  if (!d) return false;
  d.open = true;
  d.scrollIntoView();
  return true;
}
document.querySelectorAll('.cell').forEach(el => {
  el.addEventListener('mouseenter', ev => {
    tip.replaceChildren(...pointsOf(el).map(describe));
    tip.style.left = (ev.clientX + 16) + 'px';
    tip.style.top = Math.max(8, ev.clientY - 40) + 'px';
    tip.hidden = false;
  });
  el.addEventListener('mouseleave', () => { tip.hidden = true; });
  el.addEventListener('click', () => {
    for (const i of pointsOf(el)) if (data.points[i].replayed && openPoint(data.points[i].point)) return;
  });
});
document.querySelectorAll('a.open-point').forEach(a => a.addEventListener('click', ev => {
  if (openPoint(a.dataset.point)) ev.preventDefault();
}));
)JS";

std::string replay_line(const SweepPage& page, const PointSummary& p) {
  const auto t = page.first_trial.find(p.point);
  if (t == page.first_trial.end()) return "(no trial stored)";
  return "pamsim replay " + page.db_path + " --trial " + std::to_string(t->second);
}

nlohmann::json point_json(const SweepPage& page, const PointSummary& p) {
  nlohmann::json metrics = nlohmann::json::array();
  for (const MetricStats& m : p.metrics) {
    metrics.push_back({m.mean, m.std, m.min, m.max, m.count});
  }
  return {{"point", p.point},
          {"axes", p.axis_values},
          {"ok", p.ok},
          {"trials", p.trials},
          {"mistrip_rate", p.mistrip_rate()},
          {"metrics", metrics},
          {"replay", replay_line(page, p)},
          {"replayed", page.charts.count(p.point) > 0}};
}

// Which points each map's cell (grid: "ix,iy") or marker (scattered: index) stands for
nlohmann::json map_json(const SweepSummary& sweep) {
  nlohmann::json map;
  if (sweep.design == "grid") {
    nlohmann::json cells = nlohmann::json::object();
    for (std::size_t i = 0; i < sweep.points.size(); ++i) {
      const auto [ix, iy] = grid_cell_of(sweep, sweep.points[i].point);
      cells[std::to_string(ix) + "," + std::to_string(iy)].push_back(i);
    }
    map["cells"] = cells;
  } else {
    nlohmann::json points = nlohmann::json::array();
    for (std::size_t i = 0; i < sweep.points.size(); ++i) points.push_back(i);
    map["points"] = points;
  }
  return map;
}

std::string page_json(const SweepPage& page) {
  const SweepSummary& sweep = *page.sweep;
  nlohmann::json data = {{"axes", sweep.axis_keys}, {"metrics", sweep.metric_names}};
  for (const PointSummary& p : sweep.points) data["points"].push_back(point_json(page, p));
  data["maps"] = nlohmann::json::object();
  if (sweep.axis_keys.size() >= 2) {
    for (const std::string& metric : page.heat_metrics)
      data["maps"]["map-" + metric] = map_json(sweep);
  }
  return json_for_script(data.dump());
}

std::string stats_cell(const MetricStats& m) {
  if (m.count == 0) return "n/a";
  return short_number(m.mean) + (std::isfinite(m.std) ? " \u00b1 " + short_number(m.std) : "");
}

std::string points_table(const SweepPage& page) {
  const SweepSummary& sweep = *page.sweep;
  const std::vector<std::string> shown = default_table_metrics(sweep, page.metric);
  std::ostringstream s;
  s << "<table id=\"points\"><tr><th>point</th>";
  for (const std::string& a : sweep.axis_keys) s << "<th>" << html_escape(a) << "</th>";
  s << "<th>ok</th>";
  for (const std::string& m : shown) s << "<th>" << html_escape(m) << " (mean \u00b1 SD)</th>";
  s << "<th>its trials</th></tr>\n";
  for (const PointSummary& p : sweep.points) {
    s << "<tr><td>" << p.point << "</td>";
    for (const std::string& v : p.axis_values) s << "<td>" << html_escape(v) << "</td>";
    s << "<td>" << p.ok << " / " << p.trials << "</td>";
    for (const std::string& m : shown) {
      const int k = sweep.metric_index(m);
      s << "<td>" << (k < 0 ? "n/a" : stats_cell(p.metrics[static_cast<std::size_t>(k)]))
        << "</td>";
    }
    s << "<td>"
      << (page.charts.count(p.point)
              ? "<a class=\"open-point\" href=\"#point-" + std::to_string(p.point) +
                    "\" data-point=\"" + std::to_string(p.point) + "\">replayed below</a>"
              : "<code>" + html_escape(replay_line(page, p)) + "</code>")
      << "</td></tr>\n";
  }
  s << "</table>";
  return s.str();
}

std::string replayed_sections(const SweepPage& page) {
  std::ostringstream s;
  for (const PointSummary* p : page.replayed) {
    const auto charts = page.charts.find(p->point);
    if (charts == page.charts.end()) continue;
    std::string setting;
    for (std::size_t a = 0; a < page.sweep->axis_keys.size(); ++a) {
      setting += (a ? ", " : "") + page.sweep->axis_keys[a] + " = " + p->axis_values[a];
    }
    s << "<details class=\"trials\" id=\"point-" << p->point << "\"><summary>Point " << p->point
      << ": " << html_escape(setting) << "</summary>";
    for (const LineChart& c : charts->second) s << svg_line_chart(c);
    s << "<p><code>" << html_escape(replay_line(page, *p)) << "</code></p></details>\n";
  }
  return s.str();
}

}  // namespace

std::string sweep_report_html(const SweepPage& page) {
  const SweepSummary& sweep = *page.sweep;
  std::ostringstream body;
  body << "<h1>Sweep " << html_escape(sweep.sweep_file) << "</h1>\n<p>" << html_escape(sweep.design)
       << " design, " << sweep.points_total << " points \u00d7 " << sweep.seeds << " seeds; "
       << sweep.trials_stored << " of " << sweep.trials_total << " trials stored, "
       << sweep.trials_not_ok << " diverged or failed. Database <code>" << html_escape(page.db_path)
       << "</code>.</p>\n<p>Best: " << html_escape(best_criterion(sweep, page.metric)) << ".</p>\n";
  if (sweep.axis_keys.size() >= 2) {
    body << "<h2>Heat maps</h2>\n<p>Hover a cell for its points' metrics over the seeds; click a "
            "replayed point's cell (the best are outlined in red) for its trials.</p>\n";
    const PointSummary* best = page.best.empty() ? nullptr : page.best.front();
    for (const std::string& metric : page.heat_metrics) {
      body << svg_heat_map(sweep_heat_map(sweep, metric, best, page.metric), "map-" + metric)
           << "\n";
    }
  }
  body << "<h2>Trials replayed: the best points and those asked for</h2>\n"
       << replayed_sections(page) << "<h2>Every point</h2>\n"
       << points_table(page) << "\n<script type=\"application/json\" id=\"page-data\">"
       << page_json(page) << "</script>";
  return html_document("pamsim report: " + sweep.sweep_file, body.str(), kScript, page.footer_html);
}

}  // namespace pamsim
