// Numbers as text, whatever the host's locale: every number libdbs writes (result files,
// summary.json, meshes, pictures, error messages) goes through here. std::to_chars never
// consults the locale, so a host that set a comma locale (common in CAD programs) still gets
// "0.001", never "0,001".
#pragma once
#include <string>

namespace dbs {

/// Appends the shortest text that reads back to the same double ("inf", "-inf", "nan" for
/// non-finite values).
void append_shortest(std::string& out, double x);

/// The shortest text that reads back to the same double.
std::string shortest_text(double x);

/// `x` with `digits` significant digits (1..17), as printf's %g would write it in the C
/// locale but without the exponent's leading zero: "0.00123", "1.5e-6", "2e+12".
std::string significant_text(double x, int digits);

}  // namespace dbs
