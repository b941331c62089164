// A small TOML emitter: toml++ sorts keys alphabetically and prints floats
// with 17 digits; a resolved scenario reads better in the documented key
// order with the shortest digits that read back to the same double.
#include <fmt/format.h>

#include <cmath>

#include "talus/scenario/scenario_detail.hpp"

namespace talus::io::detail {
namespace {

using Json = nlohmann::ordered_json;

bool is_array_of_tables(const Json& v) {
  if (!v.is_array() || v.empty()) return false;
  for (const Json& e : v) {
    if (!e.is_object()) return false;
  }
  return true;
}

bool is_plain(const Json& v) {
  if (v.is_object()) return false;
  if (v.is_array()) {
    for (const Json& e : v) {
      if (!is_plain(e)) return false;
    }
  }
  return true;
}

// Small tables of plain values ({min = [..], max = [..]}) stay on one line.
bool is_inline_table(const Json& v) {
  if (!v.is_object() || v.size() > 3) return false;
  for (const auto& [key, value] : v.items()) {
    if (!is_plain(value)) return false;
  }
  return true;
}

bool is_section(const Json& v) {
  return (v.is_object() && !is_inline_table(v)) || is_array_of_tables(v);
}

// A TOML basic string: quotes, backslashes and control characters other than
// tab escaped (TOML forbids them raw), so that any text read back is the same.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\', out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if ((u < 0x20 && c != '\t') || u == 0x7F) {
      out += fmt::format("\\u{:04X}", u);
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string key_text(const std::string& key) {
  const bool bare =
      !key.empty() && key.find_first_not_of(
                          "abcdefghijklmnopqrstuvwxyz"
                          "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") == std::string::npos;
  return bare ? key : quoted(key);
}

std::string value_text(const Json& v) {
  if (v.is_string()) return quoted(v.get<std::string>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return fmt::format("{}", v.get<std::int64_t>());
  if (v.is_number_float()) {
    const double x = v.get<double>() + 0.0;  // -0.0 written as 0.0
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    if (std::isnan(x)) return "nan";
    std::string text = fmt::format("{}", x);  // shortest round-trip digits
    // TOML floats need a fraction or an exponent ("2672" would be an integer).
    if (text.find_first_of(".eE") == std::string::npos) text += ".0";
    return text;
  }
  std::string text;
  if (v.is_array()) {
    for (const Json& e : v) text += (text.empty() ? "" : ", ") + value_text(e);
    return "[" + text + "]";
  }
  if (v.is_object()) {
    for (const auto& [key, value] : v.items()) {
      text += (text.empty() ? "" : ", ") + key_text(key) + " = " + value_text(value);
    }
    return "{ " + text + " }";
  }
  return "\"\"";  // null: not produced by the writer
}

void emit_table(std::string& out, const Json& table, const std::string& prefix) {
  for (const auto& [key, value] : table.items()) {
    if (!is_section(value)) out += key_text(key) + " = " + value_text(value) + "\n";
  }
  for (const auto& [key, value] : table.items()) {
    const std::string name = prefix + key_text(key);
    if (value.is_object() && is_section(value)) {
      out += "\n[" + name + "]\n";
      emit_table(out, value, name + ".");
    } else if (is_array_of_tables(value)) {
      for (const Json& element : value) {
        out += "\n[[" + name + "]]\n";
        emit_table(out, element, name + ".");
      }
    }
  }
}

}  // namespace

std::string json_to_toml(const nlohmann::ordered_json& root) {
  std::string out;
  emit_table(out, root, "");
  return out;
}

}  // namespace talus::io::detail
