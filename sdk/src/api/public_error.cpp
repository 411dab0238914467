#include "api/public_error.hpp"

#include <string>

#include "core/error.hpp"
#include "pipeline/pipeline.hpp"

namespace onetip::api {

void rethrowAsPublicError() {
  try {
    throw;
  } catch (const Error&) {
    throw;
  } catch (const InputError& e) {
    throw Error(ErrorKind::input, e.what());
  } catch (const pipeline::PipelineStateError& e) {
    throw Error(ErrorKind::state, e.what());
  } catch (const std::exception& e) {
    throw Error(ErrorKind::internal, std::string("internal error: ") + e.what());
  } catch (...) {
    throw Error(ErrorKind::internal, "internal error: unknown exception");
  }
}

}  // namespace onetip::api
