// JSON values through nlohmann::json: the --json outputs, the --stats files,
// and what the tests and benchmarks read back.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace tsis {

// Objects keep their keys in insertion order, so outputs read in the order
// written.
using Json = nlohmann::ordered_json;

// `j` as text, `indent` spaces a level (negative: on one line). tsis computes
// its numbers as doubles: those with an integral value print as integers
// ("3", not "3.0"), non-finite ones as null (JSON has no inf or NaN).
std::string dumpJson(const Json& j, int indent = 2);

}  // namespace tsis
