// The shared helpers of the core tests: what a call throws (error_code_of, throws,
// expect_error) and files in DBS_TEST_TMP_DIR (so each test shows exactly what it feeds).
// Include after the dbs headers: cmocka's fail() macro would hide dbs::fail.
#pragma once
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <string>

#include "error.hpp"

// cmocka last, with C linkage.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

namespace core_test {

/// The code of the dbs::Error that `call` throws; ErrorCode::Internal when it throws none.
template <typename Call>
dbs::ErrorCode error_code_of(Call call) {
  try {
    call();
  } catch (const dbs::Error& e) {
    return e.code();
  }
  return dbs::ErrorCode::Internal;  // "nothing thrown"
}

/// True when `call` throws dbs::Error with `code`.
template <typename Call>
bool throws(dbs::ErrorCode code, Call call) {
  try {
    call();
  } catch (const dbs::Error& e) {
    return e.code() == code;
  }
  return false;
}

/// Runs `call`, which must throw dbs::Error with `code` and a message holding every fragment.
template <typename Call>
void expect_error(Call call, dbs::ErrorCode code, std::initializer_list<std::string> fragments) {
  try {
    call();
  } catch (const dbs::Error& e) {
    if (e.code() != code) fail_msg("error code %d, expected %d; message: %s", static_cast<int>(e.code()), static_cast<int>(code), e.what());
    for (const std::string& fragment : fragments) {
      if (std::strstr(e.what(), fragment.c_str()) == nullptr) fail_msg("message \"%s\" lacks \"%s\"", e.what(), fragment.c_str());
    }
    return;
  }
  fail_msg("no dbs::Error thrown (expected code %d)", static_cast<int>(code));
}

/// A path in the test's scratch directory.
inline std::string tmp_path(const std::string& name) { return std::string(DBS_TEST_TMP_DIR) + "/" + name; }

/// Writes `bytes` (text or binary) to tmp_path(name) and returns the path.
inline std::string write_tmp(const std::string& name, const std::string& bytes) {
  const std::string path = tmp_path(name);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  assert_non_null(f);
  assert_int_equal(std::fwrite(bytes.data(), 1, bytes.size(), f), bytes.size());
  assert_int_equal(std::fclose(f), 0);
  return path;
}

/// The whole content of the file at `path` (which must exist).
inline std::string read_all(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  assert_non_null(f);
  std::string bytes;
  char buf[4096];
  std::size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, f)) > 0) bytes.append(buf, got);
  std::fclose(f);
  return bytes;
}

}  // namespace core_test
