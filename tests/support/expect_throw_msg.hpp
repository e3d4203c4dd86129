// EXPECT_THROW_MSG as in fmt's tests: a wrong message shows both texts.
#pragma once

#include <gtest/gtest.h>

#include <exception>
#include <functional>
#include <string>

namespace mdrsim::test {

/// What `statement` throws as E, or a description of what happened instead.
template <class E>
std::string thrown_message(const std::function<void()>& statement) {
  try {
    statement();
  } catch (const E& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("<other exception> ") + e.what();
  }
  return "<no exception>";
}

}  // namespace mdrsim::test

#define EXPECT_THROW_MSG(statement, expected_exception, expected_message)           \
  EXPECT_EQ(::mdrsim::test::thrown_message<expected_exception>([&] { statement; }), \
            expected_message)
