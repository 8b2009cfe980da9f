// File and text helpers shared by the point-cloud, boundary and result files: whole files
// read and written in one go, lines with '#' comments and surrounding blanks removed, and
// numbers parsed with std::from_chars.
#pragma once
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

#include "geometry.hpp"
#include "load_progress.hpp"

namespace dbs {

/// The file's bytes. Error(Io) "cannot open 'PATH': <strerror>" (or "cannot read").
std::string read_file_bytes(const std::string& path);
/// The same, reporting the bytes read as the stage "read" (fractions 0 to 0.5) of `progress`.
std::string read_file_bytes(const std::string& path, LoadProgress& progress);

/// A file written through a memory buffer. Error(Io) "cannot create 'PATH': <strerror>" (or
/// "cannot write"); a file left unclosed by an exception is closed without a report.
class OutputFile {
 public:
  explicit OutputFile(const std::string& path);
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();
  void write(std::string_view bytes);
  /// Flushes and closes; reports a failure.
  void close();

 private:
  void flush();
  std::string path_;
  std::FILE* file_;
  std::string buffer_;
};

/// Creates or replaces the file with `bytes` (OutputFile's errors).
void write_file_bytes(const std::string& path, std::string_view bytes);

/// The file name's extension with its dot, lowercase ("" when there is none).
std::string lowercase_extension(const std::string& path);

/// Appends the shortest text that reads back to the same double (std::to_chars: no locale).
void append_number(std::string& out, double x);
/// Appends the decimal digits of `x` (no locale).
void append_integer(std::string& out, long long x);

/// "PATH:LINE" for error messages.
std::string file_line(const std::string& path, std::size_t line);

/// A short quotable excerpt of a line (long lines are cut, with "..."; control bytes as \xNN,
/// so that a NUL in a file cannot end the message early).
std::string excerpt(std::string_view text);

/// The lines of a text that hold something: each with its '#' comment removed and its
/// surrounding blanks (spaces, tabs, '\r') trimmed; lines left empty are skipped. A UTF-8
/// byte-order mark at the start (as some editors write) is skipped.
class ContentLines {
 public:
  explicit ContentLines(std::string_view text);
  /// The next non-blank line; false at the end of the text.
  bool next(std::string_view& line);
  /// 1-based number of the line last returned.
  std::size_t number() const { return number_; }
  /// Bytes of the text read so far (up to the end of the line last returned).
  std::size_t offset() const { return size_ - rest_.size(); }

 private:
  std::size_t size_;
  std::string_view rest_;
  std::size_t number_ = 0;
};

/// Parses a whole token as a number (a leading '+' allowed). Non-finite spellings (nan,
/// inf) are numbers; values beyond the double range become +-inf or +-0 as with strtod in
/// the C locale, whatever the host's locale.
bool parse_number(std::string_view token, double& out);

/// Outcome of reading three coordinates from the start of a line.
struct XyzFields {
  int count = 0;               // numbers read (3 on success)
  std::string_view offending;  // the token that is not a number (empty: the line ended)
  std::string_view rest;       // what follows the third number
  /// "expected 3 numbers, found 'abc'" or "expected 3 numbers, found only 2".
  std::string problem() const;
};

/// Reads up to three numbers (parse_number) separated by blanks and/or one comma into
/// `out`; finiteness is the caller's business.
XyzFields parse_xyz_fields(std::string_view line, Vec3& out);

}  // namespace dbs
