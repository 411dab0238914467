// api/public_error.hpp — the public API's error boundary: every internal
// exception becomes an onetip::Error with a kind (onetip/error.hpp).
//   InputError (bad files, sources, options)     -> ErrorKind::input
//   PipelineStateError (wrong call order)         -> ErrorKind::state
//   onetip::Error                                  -> unchanged
//   any other std::exception or anything else      -> ErrorKind::internal
#pragma once

#include <utility>

#include "onetip/error.hpp"

namespace onetip::api {

// Call inside a catch block: rethrows the exception being handled as onetip::Error.
[[noreturn]] void rethrowAsPublicError();

// Runs fn(); exceptions leave as onetip::Error.
template <typename Fn>
decltype(auto) withPublicErrors(Fn&& fn) {
  try {
    return std::forward<Fn>(fn)();
  } catch (...) {
    rethrowAsPublicError();
  }
}

}  // namespace onetip::api
