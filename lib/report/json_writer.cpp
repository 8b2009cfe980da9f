#include "json_writer.hpp"

#include <cmath>
#include <cstdio>

#include "error.hpp"
#include "number_text.hpp"

namespace dbs {
namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

void JsonWriter::open_value(const char* key) {
  if (!has_items_.empty()) {
    if (has_items_.back()) text_ += ",";
    has_items_.back() = true;
    text_ += "\n" + std::string(2 * has_items_.size(), ' ');
  } else if (!text_.empty()) {
    fail(ErrorCode::Internal, "JsonWriter: a second top-level value");
  }
  if (key) text_ += quoted(key) + ": ";
}

void JsonWriter::close(char bracket) {
  if (has_items_.empty()) fail(ErrorCode::Internal, "JsonWriter: closing with nothing open");
  bool had_items = has_items_.back();
  has_items_.pop_back();
  if (had_items) text_ += "\n" + std::string(2 * has_items_.size(), ' ');
  text_ += bracket;
}

void JsonWriter::begin_object(const char* key) {
  open_value(key);
  text_ += "{";
  has_items_.push_back(false);
}

void JsonWriter::end_object() { close('}'); }

void JsonWriter::begin_array(const char* key) {
  open_value(key);
  text_ += "[";
  has_items_.push_back(false);
}

void JsonWriter::end_array() { close(']'); }

void JsonWriter::number(const char* key, double value) {
  open_value(key);
  if (!std::isfinite(value)) {
    text_ += "null";
    return;
  }
  append_shortest(text_, value);  // round-trips exactly, in any locale
}

void JsonWriter::integer(const char* key, long long value) {
  open_value(key);
  text_ += std::to_string(value);
}

void JsonWriter::boolean(const char* key, bool value) {
  open_value(key);
  text_ += value ? "true" : "false";
}

void JsonWriter::string(const char* key, const std::string& value) {
  open_value(key);
  text_ += quoted(value);
}

const std::string& JsonWriter::text() const {
  if (!has_items_.empty()) fail(ErrorCode::Internal, "JsonWriter: " + std::to_string(has_items_.size()) + " containers still open");
  return text_;
}

}  // namespace dbs
