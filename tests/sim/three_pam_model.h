// three_pam_model.h: models/arm_2pam.xml with a second agonist beside the first (same
// anchor, shaft side and attachment, tendon "ago2_line", actuator "agonist2"): a model no code
// in pamsim knows, bound only by its actuator names.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "cli_util.h"

namespace pamsim_test {

inline std::string three_pam_model() {
  std::string xml = read_file(std::string(PAMSIM_SOURCE_DIR) + "/models/arm_2pam.xml");
  const auto insert_before = [&](const std::string& anchor, const std::string& text) {
    const auto at = xml.find(anchor);
    EXPECT_NE(at, std::string::npos) << anchor;
    if (at != std::string::npos) xml.insert(at, text);
  };
  insert_before("  </tendon>",
                "    <spatial name=\"ago2_line\" width=\"0.003\">\n"
                "      <site site=\"ago_anchor\"/>\n"
                "      <geom geom=\"shaft\" sidesite=\"ago_side\"/>\n"
                "      <site site=\"ago_attach\"/>\n"
                "    </spatial>\n");
  insert_before("  </actuator>",
                "    <general name=\"agonist2\" tendon=\"ago2_line\" dyntype=\"none\" "
                "gaintype=\"fixed\" gainprm=\"0\" biastype=\"user\" forcelimited=\"true\" "
                "forcerange=\"-2000 0\"/>\n");
  return xml;
}

}  // namespace pamsim_test
