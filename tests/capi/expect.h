// Assertions for C API tests: a call's result with the library's message
// when it fails, and failures that must name what was wrong.
#pragma once

#include <proxima/proxima.h>

#include <gtest/gtest.h>

#include <string>

#define EXPECT_OK(call)                                                                                 \
  do {                                                                                                  \
    const proxResult r_ = (call);                                                                       \
    EXPECT_EQ(r_, PROX_SUCCESS) << #call << ": " << proxResultString(r_) << ": " << proxGetLastError(); \
  } while (0)
#define ASSERT_OK(call)                                                                                 \
  do {                                                                                                  \
    const proxResult r_ = (call);                                                                       \
    ASSERT_EQ(r_, PROX_SUCCESS) << #call << ": " << proxResultString(r_) << ": " << proxGetLastError(); \
  } while (0)
// The call fails with `code` and the message names `word`.
#define EXPECT_FAILS(call, code, word)                                                              \
  do {                                                                                              \
    EXPECT_EQ((call), (code)) << #call;                                                             \
    EXPECT_NE(std::string(proxGetLastError()).find(word), std::string::npos)                        \
        << #call << ": message '" << proxGetLastError() << "' does not mention '" << (word) << "'"; \
  } while (0)
