// The one family of errors (core/errors.h): every kind is a pond::Error, and none is another.
#include <gtest/gtest.h>

#include <type_traits>

#include "core/errors.h"

namespace pond {
namespace {

static_assert(std::is_base_of_v<Error, InputError> && std::is_base_of_v<Error, RuntimeError> &&
              std::is_base_of_v<Error, InternalError>);
static_assert(!std::is_base_of_v<InputError, InternalError> && !std::is_base_of_v<RuntimeError, InternalError>);

TEST(Errors, AnInternalErrorIsNotBadInput) {
  try {
    throw InternalError("a broken invariant");
  } catch (const InputError&) {
    FAIL() << "an internal error was caught as bad input (exit 2)";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "a broken invariant");
  }
}

}  // namespace
}  // namespace pond
