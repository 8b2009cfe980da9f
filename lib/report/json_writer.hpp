// A minimal streaming JSON writer for report files: objects, arrays, strings, numbers
// (non-finite numbers become null), indented two spaces.
#pragma once
#include <string>
#include <vector>

namespace dbs {

class JsonWriter {
 public:
  void begin_object(const char* key = nullptr);
  void end_object();
  void begin_array(const char* key = nullptr);
  void end_array();
  void number(const char* key, double value);
  void integer(const char* key, long long value);
  void boolean(const char* key, bool value);
  void string(const char* key, const std::string& value);
  /// A number without a key (an array element).
  void number(double value) { number(nullptr, value); }

  /// The document; all objects and arrays must be closed.
  const std::string& text() const;

 private:
  void open_value(const char* key);
  void close(char bracket);

  std::string text_;
  std::vector<bool> has_items_;  // per open container
};

}  // namespace dbs
