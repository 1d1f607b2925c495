// html_page_test.cc: the pieces of a self-contained HTML page (html_page.h): text escaped,
// JSON that cannot close its script element, a heat map's cells with their place and text,
// and a trial's charts: one position series per trial, thinned to the limit, and the first
// trial's commanded and chamber pressures (not the sensor's); a command's Markdown as HTML, its
// pipe tables as tables and any raw HTML left out.
#include "sim/io/html_page.h"

#include <gtest/gtest.h>

#include "sim/io/markdown_html.h"

#include <string>

namespace pamsim {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

TEST(HtmlPageTest, TextIsEscapedAndJsonCannotCloseItsScript) {
  EXPECT_EQ(html_escape("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
  EXPECT_EQ(json_for_script(R"({"s":"</script><b>"})"), R"({"s":"<\/script><b>"})");
  EXPECT_EQ(short_number(12.586636), "12.59");
  EXPECT_EQ(short_number(NAN), "n/a");
}

TEST(HtmlPageTest, AHeatMapsCellsSayWhereTheyLieAndWhatTheyHold) {
  HeatMap map;
  map.title = "drop <deg>";
  map.x_levels = {"1", "2", "3"};
  map.y_levels = {"a", "b"};
  map.cells = {1, 2, 3, 4, 5, NAN};
  map.has_mark = true;
  map.mark_x = 2;
  map.mark_y = 0;
  const std::string svg = svg_heat_map(map, "m1");
  EXPECT_EQ(count(svg, "class=\"cell"), 6u);
  EXPECT_EQ(count(svg, "class=\"cell marked\" data-map=\"m1\" data-ix=\"2\" data-iy=\"0\""), 1u);
  EXPECT_NE(svg.find("drop &lt;deg&gt;"), std::string::npos);
  EXPECT_NE(svg.find("fill=\"#c8c8c8\"><title>n/a</title>"), std::string::npos);  // no value
  EXPECT_NE(svg.find("<title>5</title>"), std::string::npos);
}

TEST(HtmlPageTest, AScatteredDesignsPointsAreMarkersAndTheBestIsMarked) {
  HeatMap map;
  map.scattered = true;
  map.x = {20, 80, 150};
  map.y = {0.001, 0.01, 0.004};
  map.values = {3, 1, 2};
  map.has_mark = true;
  map.mark_x = 80;
  map.mark_y = 0.01;
  const std::string svg = svg_heat_map(map, "m2");
  EXPECT_EQ(count(svg, "<circle class=\"cell"), 3u);
  EXPECT_EQ(count(svg, "class=\"cell marked\" data-map=\"m2\" data-i=\"1\""), 1u);
  EXPECT_NE(svg.find(">0.01</text>"), std::string::npos);  // the y range's top
}

TEST(HtmlPageTest, ATrialsChartsArePositionPerTrialAndTheFirstTrialsPressures) {
  Trajectory t;
  t.columns = {"time_s",    "angle_deg",      "p_cmd_ago_MPa",
               "p_ago_MPa", "p_meas_ago_MPa", "force_ago_N"};
  for (int r = 0; r < 2000; ++r) {
    for (double v : {r * 0.001, r * 0.01, 0.4, 0.41, 0.42, 10.0}) t.values.push_back(v);
  }
  const std::vector<LineChart> charts = trial_charts({{"seed 1", &t}, {"seed 2", &t}}, 800);
  ASSERT_EQ(charts.size(), 2u);
  ASSERT_EQ(charts[0].series.size(), 2u);
  EXPECT_EQ(charts[0].y_label, "angle_deg");
  EXPECT_EQ(charts[0].series[0].x.size(), 667u);  // every 3rd of 2000 rows: at most 800
  EXPECT_DOUBLE_EQ(charts[0].series[0].y[2], 0.06);
  ASSERT_EQ(charts[1].series.size(), 2u);
  EXPECT_EQ(charts[1].series[0].label, "p_cmd_ago_MPa");
  EXPECT_EQ(charts[1].series[1].label, "p_ago_MPa");
  const std::string svg = svg_line_chart(charts[1]);
  EXPECT_EQ(count(svg, "<polyline"), 2u);
}

TEST(HtmlPageTest, MarkdownTablesBecomeTablesAndRawHtmlIsLeftOut) {
  const std::string html = markdown_to_html(
      "# Table V\n\nEach cell: `max / RMSE`.\n\n| method | agonist |\n| --- | --- |\n"
      "| model | 2.6 / 1.4 (8.82 / 5.24) |\n\n- a\n- b\n\n<script>alert(1)</script>\n");
  EXPECT_NE(html.find("<h1>Table V</h1>"), std::string::npos) << html;
  EXPECT_NE(html.find("<code>max / RMSE</code>"), std::string::npos) << html;
  EXPECT_NE(html.find("<th>method</th>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>2.6 / 1.4 (8.82 / 5.24)</td>"), std::string::npos) << html;
  EXPECT_EQ(count(html, "<li>"), 2u);
  EXPECT_EQ(html.find("<script>"), std::string::npos) << html;
}

}  // namespace
}  // namespace pamsim
