#include "text_io.hpp"

#include <cctype>
#include <cmath>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "error.hpp"
#include "number_text.hpp"

namespace dbs {

namespace {

/// An I/O failure: `what` and the system's reason, with its errno (read first: building the
/// message must not change it).
[[noreturn]] void fail_with_errno(const std::string& what) {
  const int error = errno;
  fail_io(what + ": " + std::strerror(error), error);
}

}  // namespace

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool is_field_end(char c) { return is_blank(c) || c == ','; }

std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && is_blank(s[b])) ++b;
  while (e > b && is_blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

}  // namespace

bool parse_number(std::string_view token, double& out) {
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = first + token.size();
  if (*first == '+' && token.size() > 1 && first[1] != '-' && first[1] != '+') ++first;
  const auto [end, ec] = std::from_chars(first, last, out);
  if (end != last) return false;
  // from_chars leaves values beyond the double range unset: they get their IEEE meaning
  // (overflow -> +-inf, underflow -> +-0), decided from the decimal exponent (strtod would
  // follow the host's locale: under a comma locale "1.5e400" reads as 1).
  if (ec == std::errc::result_out_of_range) {
    const std::string_view text(first, static_cast<std::size_t>(last - first));
    const std::size_t e = text.find_first_of("eE");
    const std::string_view mantissa = text.substr(0, e);
    long exponent = 0;
    if (e != std::string_view::npos) {
      const char* x = text.data() + e + 1;
      if (x < last && *x == '+') ++x;
      if (std::from_chars(x, last, exponent).ec != std::errc()) exponent = *x == '-' ? -100000 : 100000;  // beyond long
    }
    // the decimal exponent D of the value (in [10^D, 10^(D+1))): the exponent plus that of
    // the mantissa's first non-zero digit; out of range, D > 0 is an overflow, D < 0 an underflow
    const bool negative = !mantissa.empty() && mantissa.front() == '-';
    const std::size_t point = mantissa.find('.');
    const std::size_t nonzero = mantissa.find_first_of("123456789");
    long magnitude = exponent;
    if (nonzero != std::string_view::npos) {
      if (point == std::string_view::npos || nonzero < point) magnitude += static_cast<long>((point == std::string_view::npos ? mantissa.size() : point) - nonzero) - 1;
      else magnitude -= static_cast<long>(nonzero - point);
    }
    out = magnitude > 0 ? (negative ? -HUGE_VAL : HUGE_VAL) : (negative ? -0.0 : 0.0);
    return true;
  }
  return ec == std::errc();
}

void append_number(std::string& out, double x) { append_shortest(out, x); }

void append_integer(std::string& out, long long x) {
  char buf[24];
  const auto end = std::to_chars(buf, buf + sizeof buf, x).ptr;
  out.append(buf, end);
}

std::string lowercase_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::string read_file_bytes(const std::string& path) {
  LoadProgress none;
  return read_file_bytes(path, none);
}

std::string read_file_bytes(const std::string& path, LoadProgress& progress) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) fail_with_errno("cannot open '" + path + "'");
  std::string bytes;
  std::error_code size_error;
  const auto size = std::filesystem::file_size(path, size_error);
  if (!size_error) bytes.reserve(static_cast<std::size_t>(size));
  progress.begin("read", 0.0, 0.5, size_error ? 0 : static_cast<std::uint64_t>(size));
  char chunk[1 << 16];
  std::size_t got;
  while ((got = std::fread(chunk, 1, sizeof chunk, file.get())) > 0) {
    bytes.append(chunk, got);
    progress.at(bytes.size());
  }
  if (std::ferror(file.get())) fail_with_errno("cannot read '" + path + "'");
  return bytes;
}

OutputFile::OutputFile(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "wb")) {
  if (!file_) fail_with_errno("cannot create '" + path + "'");
}

OutputFile::~OutputFile() {
  if (file_) std::fclose(file_);
}

void OutputFile::write(std::string_view bytes) {
  constexpr std::size_t kFlushSize = 1 << 20;
  buffer_.append(bytes.data(), bytes.size());
  if (buffer_.size() >= kFlushSize) flush();
}

void OutputFile::flush() {
  if (std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) fail_with_errno("cannot write '" + path_ + "'");
  buffer_.clear();
}

void OutputFile::close() {
  flush();
  std::FILE* file = file_;
  file_ = nullptr;
  if (std::fclose(file) != 0) fail_with_errno("cannot write '" + path_ + "'");
}

void write_file_bytes(const std::string& path, std::string_view bytes) {
  OutputFile file(path);
  file.write(bytes);
  file.close();
}

std::string file_line(const std::string& path, std::size_t line) { return path + ":" + std::to_string(line); }

std::string excerpt(std::string_view text) {
  constexpr std::size_t kMax = 40;
  const std::string_view shown = text.substr(0, kMax);
  // Control bytes are written as \xNN: a NUL would end the C string of the message there.
  std::string out;
  for (char c : shown) {
    const unsigned char b = static_cast<unsigned char>(c);
    if (b < 0x20 && c != '\t') {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 15];
    } else {
      out += c;
    }
  }
  return text.size() <= kMax ? out : out + "...";
}

ContentLines::ContentLines(std::string_view text) : size_(text.size()), rest_(text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (rest_.substr(0, kByteOrderMark.size()) == kByteOrderMark) rest_.remove_prefix(kByteOrderMark.size());
}

bool ContentLines::next(std::string_view& line) {
  while (!rest_.empty()) {
    const std::size_t eol = rest_.find('\n');
    std::string_view raw = rest_.substr(0, eol);
    rest_ = eol == std::string_view::npos ? std::string_view() : rest_.substr(eol + 1);
    ++number_;
    const std::size_t hash = raw.find('#');
    if (hash != std::string_view::npos) raw = raw.substr(0, hash);
    line = trim(raw);
    if (!line.empty()) return true;
  }
  return false;
}

std::string XyzFields::problem() const {
  if (!offending.empty()) return "expected 3 numbers, found '" + excerpt(offending) + "'";
  return "expected 3 numbers, found only " + std::to_string(count);
}

XyzFields parse_xyz_fields(std::string_view line, Vec3& out) {
  XyzFields fields;
  const char* p = line.data();
  const char* const end = p + line.size();
  for (int i = 0; i < 3; ++i) {
    if (i > 0) {
      // separator: blanks, at most one comma, blanks
      while (p < end && is_blank(*p)) ++p;
      if (p < end && *p == ',') {
        ++p;
        while (p < end && is_blank(*p)) ++p;
      }
    }
    const char* token_end = p;
    while (token_end < end && !is_field_end(*token_end)) ++token_end;
    const std::string_view token(p, static_cast<std::size_t>(token_end - p));
    if (token.empty()) {
      // the line ended, or an empty field between two commas / a leading comma
      fields.offending = p < end ? std::string_view(p, 1) : std::string_view();
      return fields;
    }
    if (!parse_number(token, out[i])) {
      fields.offending = token;
      return fields;
    }
    p = token_end;
    ++fields.count;
  }
  fields.rest = std::string_view(p, static_cast<std::size_t>(end - p));
  return fields;
}

}  // namespace dbs
