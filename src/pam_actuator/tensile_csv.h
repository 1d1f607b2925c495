// tensile_csv.h: tensile-test data as CSV, the format `pamsim tensile` writes and
// `pamsim fit` reads. A header row names the columns; pressure_MPa, deformation_mm,
// force_N and length_mm are required in any order, direction (loading | unloading) is
// optional, any other column is ignored.
#pragma once

#include <string>
#include <vector>

#include "pam_actuator/tensile_test.h"

namespace pamsim {

// CSV text with the header pressure_MPa,deformation_mm,force_N,length_mm,direction.
std::string tensile_rows_to_csv(const std::vector<TensileRow>& rows);

// Reads a tensile CSV file. Throws InputError naming the file and the row / column for a
// missing file, a missing column, a non-numeric or non-finite cell, a negative pressure,
// a bad direction, a row with too few cells, or no data rows.
std::vector<TensileRow> read_tensile_csv(const std::string& path);

}  // namespace pamsim
