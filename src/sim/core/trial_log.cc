// trial_log.cc: see trial_log.h.
#include "sim/core/trial_log.h"

#include <algorithm>
#include <stdexcept>

namespace pamsim {

std::size_t Trajectory::column(const std::string& name) const {
  const auto it = std::find(columns.begin(), columns.end(), name);
  if (it == columns.end()) throw std::out_of_range("no trajectory column " + name);
  return static_cast<std::size_t>(it - columns.begin());
}

bool Trajectory::has_column(const std::string& name) const {
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

std::size_t LogLayout::column_of(const std::string& row_name, std::size_t instance) const {
  const std::vector<ChannelRow>& table = trial_channel_table();
  for (std::size_t c = 0; c < sources.size(); ++c) {
    const LogColumn& s = sources[c];
    if (!s.controller && s.instance == instance && table[s.row].name == row_name) return c;
  }
  throw std::logic_error("the log has no column " + row_name + " #" + std::to_string(instance));
}

namespace {

bool applies(const ChannelRow& row, bool hinge) {
  return row.joint == ChannelJoint::kAny || (row.joint == ChannelJoint::kHinge) == hinge;
}

// Lays out rows [first, last) of the table, muscle by muscle (the rows flagged so) or each row
// for all its instances in turn.
class LayoutBuilder {
 public:
  LayoutBuilder(LogLayout* layout, const std::vector<std::string>& bodies,
                const std::vector<std::string>& labels,
                const std::vector<ControllerChannel>& channels)
      : layout_(*layout), bodies_(bodies), labels_(labels), channels_(channels) {}

  void add_row(std::size_t r) {
    const ChannelRow& row = trial_channel_table()[r];
    if (row.controller_channels) {
      for (std::size_t k = 0; k < channels_.size(); ++k) {
        layout_.controller_quantities.push_back(
            quantity_name(channels_[k].prefix, channels_[k].suffix));
        for (std::size_t j = 0; j < labels_.size(); ++j) {
          add(channels_[k].prefix + labels_[j] + channels_[k].suffix, {0, j, true, k});
        }
      }
    } else if (row.per_muscle() || row.per_body()) {
      const std::vector<std::string>& parts = row.per_muscle() ? labels_ : bodies_;
      for (std::size_t i = 0; i < parts.size(); ++i) add(row.column(parts[i]), {r, i});
    } else {
      add(row.name, {r, 0});
    }
  }
  void add_muscle_by_muscle(const std::vector<std::size_t>& rows) {
    for (std::size_t j = 0; j < labels_.size(); ++j) {
      for (std::size_t r : rows) add(trial_channel_table()[r].column(labels_[j]), {r, j});
    }
  }

 private:
  void add(std::string name, LogColumn source) {
    layout_.columns.push_back(std::move(name));
    layout_.sources.push_back(source);
  }
  LogLayout& layout_;
  const std::vector<std::string>& bodies_;
  const std::vector<std::string>& labels_;
  const std::vector<ControllerChannel>& channels_;
};

}  // namespace

LogLayout make_log_layout(bool hinge, const std::vector<std::string>& bodies,
                          const std::vector<std::string>& labels,
                          const std::vector<ControllerChannel>& channels) {
  LogLayout layout;
  LayoutBuilder builder(&layout, bodies, labels, channels);
  const std::vector<ChannelRow>& table = trial_channel_table();
  std::vector<std::size_t> group;  // the rows written muscle by muscle, gathered
  for (std::size_t r = 0; r <= table.size(); ++r) {
    const bool grouped = r < table.size() && table[r].muscle_by_muscle && table[r].per_muscle();
    if (!grouped && !group.empty()) {
      builder.add_muscle_by_muscle(group);
      group.clear();
    }
    if (r == table.size() || !applies(table[r], hinge)) continue;
    if (grouped) {
      group.push_back(r);
    } else {
      builder.add_row(r);
    }
  }
  layout.time = layout.column_of("time_s");
  layout.joint_position = layout.column_of(hinge ? "angle_deg" : "position_mm");
  layout.joint_velocity = layout.column_of(hinge ? "omega_deg_s" : "velocity_mm_s");
  return layout;
}

void write_log_row(const LogLayout& layout, const TrialObservation& o, double* row) {
  const std::vector<ChannelRow>& table = trial_channel_table();
  for (std::size_t c = 0; c < layout.sources.size(); ++c) {
    const LogColumn& s = layout.sources[c];
    row[c] = s.controller ? o.channels[s.channel][s.instance] : table[s.row].value(o, s.instance);
  }
}

std::vector<ObservedQuantity> observed_quantities(const LogLayout& layout,
                                                  const TrialObservation& o) {
  const std::vector<ChannelRow>& table = trial_channel_table();
  std::vector<ObservedQuantity> out;
  std::vector<double> row(layout.columns.size());
  write_log_row(layout, o, row.data());
  for (std::size_t c = 0; c < layout.sources.size(); ++c) {
    const LogColumn& s = layout.sources[c];
    const ChannelRow& r = table[s.row];
    ObservedQuantity q;
    if (s.controller) {
      q.name = layout.controller_quantities[s.channel];
      q.per_muscle = true;
    } else {
      q.name = r.per_body() ? layout.columns[c] : r.quantity();
      q.unit = r.unit;
      q.per_muscle = r.per_muscle();
      q.measured = r.measured;
    }
    const auto same = [&](const ObservedQuantity& e) { return e.name == q.name; };
    auto it = std::find_if(out.begin(), out.end(), same);
    if (it == out.end()) it = out.insert(out.end(), std::move(q));
    it->values.push_back(row[c]);
  }
  return out;
}

namespace {
ChannelDoc row_doc(const ChannelRow& r, std::string column) {
  return {std::move(column), r.unit, r.to_si / r.divisor, r.meaning, r.source, r.measured};
}
}  // namespace

std::vector<ChannelDoc> channel_docs() {
  std::vector<ChannelDoc> out;
  for (const ChannelRow& r : trial_channel_table()) out.push_back(row_doc(r, r.name));
  return out;
}

std::vector<ChannelDoc> channel_docs(const LogLayout& layout,
                                     const std::vector<ControllerChannel>& channels) {
  const std::vector<ChannelRow>& table = trial_channel_table();
  std::vector<ChannelDoc> out;
  for (std::size_t c = 0; c < layout.sources.size(); ++c) {
    const LogColumn& s = layout.sources[c];
    if (s.controller) {
      out.push_back(
          {layout.columns[c], "", 1.0, channels.at(s.channel).meaning, "the controller", false});
    } else {
      out.push_back(row_doc(table[s.row], layout.columns[c]));
    }
  }
  return out;
}

}  // namespace pamsim
