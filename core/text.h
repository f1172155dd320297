// Small text helpers shared by the readers and the command line.
#pragma once

#include <string>

namespace curvbench {

/// Lower-case file extension without the dot: "ply" for "dir/Mesh.PLY", "" when there is none.
std::string lower_extension(const std::string& path);

/// s with its ASCII letters in lower case ("LHF-4" -> "lhf-4").
std::string ascii_lower(std::string s);

/// x as "%g" prints it ("1.5", "2", "1e-08").
std::string format_g(double x);

/// Parses the whole token as a double ("nan", "inf" and "-inf" included). Throws InputError
/// "<where>: '<s>' is not a number" otherwise.
double parse_double(const std::string& s, const std::string& where);

/// Parses the whole token as an integer. Throws InputError "<where>: '<s>' is not an integer".
long long parse_integer(const std::string& s, const std::string& where);

/// A JSON string literal: quoted, with '"', '\\' and control characters escaped, and "</" as
/// "<\/" so that it may sit inside an HTML <script> element.
std::string json_string(const std::string& s);

/// A JSON number in its shortest round-trip form ("0.1", "1e-300"), or null when not finite.
std::string json_number(double x);

}  // namespace curvbench
