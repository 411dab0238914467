// Fuzzes the C ABI's option entry points (bindings/c/include/onetip_c.h) and
// asserts their documented contract, so the fuzzer finds contract violations,
// not only crashes. The input drives one onetip_options struct:
//   byte 0: bit 0 the format of the final file (".json" when set, else
//           ".yaml"); bit 1 the struct starts as the next sizeof(onetip_options)
//           raw bytes (any lossless, filter, NaN...), else onetip_options_default.
//   then operations, one byte each plus operands, until the input ends:
//     set (name, index, value), get (name, index), describe (row), validate,
//     a misuse (wrong ABI version or a NULL pointer), or load (the rest of the
//     input is an options file; it ends the sequence).
// A name is a table row's (rows 0..onetip_option_count()-1) or arbitrary
// bytes; a value is a row's min, max, default, just outside the range, a
// half-integer or 8 raw bytes (NaN, infinities, denormals).
//
// Checked on every call: the return code is one the header documents for it,
// equals error.kind, and the message is NUL-terminated and "" exactly on
// success. set succeeds exactly when the name and index exist, the struct's
// lossless is 0/1 and filter a filter kind, and the value is in the row's
// closed range (a whole number unless the row is real or axes); a failed set
// leaves the struct byte-identical, a successful one reads back the value
// through get and changes no other value. describe agrees with the C++
// SensorOptions::table(); a loaded file gives, key by key, the values of the
// C++ SensorOptions::load and validates.
#include <onetip_c.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "fuzz_input_file.hpp"
#include "onetip/error.hpp"
#include "onetip/sensor_options.hpp"

namespace {

[[noreturn]] void violated(const char* what, const char* detail = "") {
  std::fprintf(stderr, "fuzz_c_options: contract violated: %s %s\n", what, detail);
  std::abort();
}

class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return pos_ >= size_; }
  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  void bytes(void* out, std::size_t n) {
    std::memset(out, 0, n);
    const std::size_t take = std::min(n, size_ - std::min(pos_, size_));
    if (take > 0) std::memcpy(out, data_ + pos_, take);
    pos_ += take;
  }
  const std::uint8_t* rest() const { return data_ + std::min(pos_, size_); }
  std::size_t restSize() const { return size_ - std::min(pos_, size_); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// The return code is one of `allowed` and agrees with the error struct.
void checkResult(int32_t rc, const onetip_error& e, std::initializer_list<int32_t> allowed, const char* call) {
  bool ok = false;
  for (int32_t a : allowed) ok = ok || rc == a;
  if (!ok) violated(call, ("returned an undocumented code " + std::to_string(rc) + ": " + e.message).c_str());
  if (e.kind != rc) violated(call, "error.kind differs from the return code");
  if (std::memchr(e.message, '\0', sizeof e.message) == nullptr) violated(call, "message not NUL-terminated");
  if ((rc == ONETIP_OK) != (e.message[0] == '\0')) violated(call, "message empty exactly when not OK");
}

onetip_option_info describeRow(int32_t row) {
  onetip_option_info info{};
  onetip_error e{};
  checkResult(onetip_option_describe(ONETIP_C_ABI_VERSION, row, &info, &e), e, {ONETIP_OK}, "describe");
  return info;
}

// The row called `name`, or -1.
int32_t rowOf(const std::string& name) {
  for (int32_t r = 0; r < onetip_option_count(); ++r)
    if (name == describeRow(r).name) return r;
  return -1;
}

bool structUsable(const onetip_options& o) {
  return (o.lossless == 0 || o.lossless == 1) && o.filter >= ONETIP_FILTER_NONE && o.filter <= ONETIP_FILTER_ONE_EURO;
}

int32_t get(const onetip_options& o, const char* name, int32_t index, double* out) {
  onetip_error e{};
  const int32_t rc = onetip_options_get(ONETIP_C_ABI_VERSION, &o, name, index, out, &e);
  checkResult(rc, e, {ONETIP_OK, ONETIP_ERROR_INPUT}, "get");
  return rc;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string readName(Input& in) {
  const std::uint8_t b = in.byte();
  if (b < 0xE0) return describeRow(b % onetip_option_count()).name;
  std::string name(static_cast<std::size_t>(in.byte() % 64), '\0');
  in.bytes(name.data(), name.size());
  return name.c_str();  // up to the first NUL, as the C side sees it
}

int32_t readIndex(Input& in) {
  const std::uint8_t b = in.byte();
  return b < 0x80 ? b % 8 - 1 : static_cast<std::int8_t>(b);
}

double readValue(Input& in, const onetip_option_info& row, int32_t index) {
  switch (in.byte() % 8) {
    case 0: return row.min;
    case 1: return row.max;
    case 2: return row.default_value[index >= 0 && index < 6 ? index : 0];
    case 3: return std::nextafter(row.min, -INFINITY);
    case 4: return std::nextafter(row.max, INFINITY);
    case 5: return (row.min + row.max) / 2;
    case 6: return static_cast<std::int8_t>(in.byte()) / 2.0;
    default: {
      double v = 0;
      in.bytes(&v, sizeof v);
      return v;
    }
  }
}

void doSet(Input& in, onetip_options& o) {
  const std::string name = readName(in);
  const int32_t row = rowOf(name);
  const onetip_option_info info = describeRow(row >= 0 ? row : 0);
  const int32_t index = readIndex(in);
  const double value = readValue(in, info, index);
  const onetip_options before = o;
  onetip_error e{};
  const int32_t rc = onetip_options_set(ONETIP_C_ABI_VERSION, &o, name.c_str(), index, value, &e);
  checkResult(rc, e, {ONETIP_OK, ONETIP_ERROR_INPUT}, "set");
  const bool whole = info.type == ONETIP_OPTION_REAL || info.type == ONETIP_OPTION_AXES || value == std::floor(value);
  const bool valid = row >= 0 && index >= 0 && index < info.count && structUsable(before) && value >= info.min &&
                     value <= info.max && whole;
  if (valid != (rc == ONETIP_OK)) violated("set", (name + ": accepted/refused against the table: " + e.message).c_str());
  if (rc != ONETIP_OK) {
    if (std::memcmp(&before, &o, sizeof o) != 0) violated("set", "a failed set changed the struct");
    return;
  }
  double back = 0;
  if (get(o, name.c_str(), index, &back) != ONETIP_OK || back != value) violated("set", "get does not read back");
  for (int32_t r = 0; r < onetip_option_count(); ++r) {
    const onetip_option_info other = describeRow(r);
    for (int32_t k = 0; k < other.count; ++k) {
      if (r == row && k == index) continue;
      double was = 0, now = 0;
      if (get(before, other.name, k, &was) != ONETIP_OK || get(o, other.name, k, &now) != ONETIP_OK)
        violated("set", "get of a table row failed on a usable struct");
      if (!sameBits(was, now)) violated("set", (name + " changed " + other.name).c_str());
    }
  }
}

void doGet(Input& in, const onetip_options& o) {
  const std::string name = readName(in);
  const int32_t row = rowOf(name);
  const int32_t index = readIndex(in);
  double out = 0;
  const int32_t rc = get(o, name.c_str(), index, &out);
  if (row < 0 || index < 0 || index >= describeRow(row).count) {
    if (rc != ONETIP_ERROR_INPUT) violated("get", "an unknown name or index was read");
  } else if (structUsable(o) && rc != ONETIP_OK) {
    violated("get", "a table row of a usable struct could not be read");
  }
}

void doDescribe(Input& in) {
  int32_t row = static_cast<std::int8_t>(in.byte());
  if (row == -128) in.bytes(&row, sizeof row);
  onetip_option_info info{};
  onetip_error e{};
  const int32_t rc = onetip_option_describe(ONETIP_C_ABI_VERSION, row, &info, &e);
  checkResult(rc, e, {ONETIP_OK, ONETIP_ERROR_INPUT}, "describe");
  const auto table = onetip::SensorOptions::table();
  const bool inTable = row >= 0 && static_cast<std::size_t>(row) < table.size();
  if (inTable != (rc == ONETIP_OK)) violated("describe", "row accepted/refused against onetip_option_count");
  if (!inTable) return;
  const onetip::OptionInfo& cpp = table[static_cast<std::size_t>(row)];
  const auto terminated = [](const char* text, std::size_t n) { return std::memchr(text, '\0', n) != nullptr; };
  if (!terminated(info.name, sizeof info.name) || !terminated(info.unit, sizeof info.unit) ||
      !terminated(info.choices, sizeof info.choices) || !terminated(info.doc, sizeof info.doc))
    violated("describe", "a string is not NUL-terminated");
  if (std::strcmp(info.name, cpp.name) != 0 || std::strcmp(info.unit, cpp.unit) != 0 ||
      info.type != static_cast<int32_t>(cpp.type) || info.count != cpp.count || info.min != cpp.min ||
      info.max != cpp.max)
    violated("describe", "differs from SensorOptions::table()");
  if ((info.count == 6) != (info.type == ONETIP_OPTION_AXES)) violated("describe", "count against type");
  for (int32_t k = 0; k < info.count; ++k)
    if (!(info.default_value[k] >= info.min && info.default_value[k] <= info.max))
      violated("describe", "default outside its range");
}

void doValidate(const onetip_options& o) {
  onetip_error e{};
  checkResult(onetip_options_validate(ONETIP_C_ABI_VERSION, &o, &e), e, {ONETIP_OK, ONETIP_ERROR_INPUT}, "validate");
}

// Wrong ABI version or a NULL pointer: the documented code, nothing changed.
void doMisuse(Input& in, onetip_options& o) {
  const std::uint8_t b = in.byte();
  const bool version = b & 1;
  const uint32_t abi = version ? ONETIP_C_ABI_VERSION + 1u + static_cast<uint32_t>(b >> 4) : ONETIP_C_ABI_VERSION;
  const int32_t expected = version ? ONETIP_ERROR_VERSION : ONETIP_ERROR_NULL_ARGUMENT;
  const onetip_options before = o;
  onetip_option_info info{};
  double out = 0;
  onetip_error e{};
  onetip_error* error = (b & 2) ? &e : nullptr;  // a NULL error struct is allowed
  int32_t rc = ONETIP_OK;
  switch ((b >> 2) % 6) {
    case 0: rc = onetip_options_default(abi, version ? &o : nullptr, error); break;
    case 1: rc = onetip_options_validate(abi, version ? &o : nullptr, error); break;
    case 2: rc = onetip_option_describe(abi, 0, version ? &info : nullptr, error); break;
    case 3: rc = onetip_options_get(abi, &o, version ? "gain" : nullptr, 0, &out, error); break;
    case 4: rc = onetip_options_set(abi, version ? &o : nullptr, "gain", 0, 1.0, error); break;
    default: rc = onetip_options_load(abi, version ? "x.yaml" : nullptr, &o, error); break;
  }
  if (error != nullptr) checkResult(rc, e, {expected}, "misuse");
  if (rc != expected) violated("misuse", "wrong code for a wrong version or a NULL pointer");
  if (std::memcmp(&before, &o, sizeof o) != 0) violated("misuse", "a refused call changed the struct");
}

void doLoad(Input& in, onetip_options& o, bool json) {
  const std::string path =
      onetip::fuzz::writeInputFile(in.rest(), in.restSize(), json ? ".json" : ".yaml");
  onetip_error e{};
  const int32_t rc = onetip_options_load(ONETIP_C_ABI_VERSION, path.c_str(), &o, &e);
  checkResult(rc, e, {ONETIP_OK, ONETIP_ERROR_INPUT}, "load");
  onetip::SensorOptions cpp;
  bool cppLoaded = true;
  try {
    cpp = onetip::SensorOptions::load(path);
  } catch (const onetip::Error&) {
    cppLoaded = false;
  }
  if (cppLoaded != (rc == ONETIP_OK)) violated("load", "the C and C++ loaders disagree");
  if (rc != ONETIP_OK) return;
  onetip_error v{};
  checkResult(onetip_options_validate(ONETIP_C_ABI_VERSION, &o, &v), v, {ONETIP_OK}, "validate after load");
  for (int32_t r = 0; r < onetip_option_count(); ++r) {
    const onetip_option_info row = describeRow(r);
    for (int32_t k = 0; k < row.count; ++k) {
      double c = 0;
      if (get(o, row.name, k, &c) != ONETIP_OK || !sameBits(c, cpp.get(row.name, k)))
        violated("load", (std::string(row.name) + " differs from SensorOptions::load").c_str());
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Input in(data, size);
  const std::uint8_t flags = in.byte();
  onetip_options o{};
  if ((flags & 2) && in.restSize() >= sizeof o) {
    in.bytes(&o, sizeof o);
  } else {
    onetip_error e{};
    checkResult(onetip_options_default(ONETIP_C_ABI_VERSION, &o, &e), e, {ONETIP_OK}, "default");
    checkResult(onetip_options_validate(ONETIP_C_ABI_VERSION, &o, &e), e, {ONETIP_OK}, "validate the defaults");
  }
  while (!in.empty()) {
    switch (in.byte() % 6) {
      case 0: doSet(in, o); break;
      case 1: doGet(in, o); break;
      case 2: doDescribe(in); break;
      case 3: doValidate(o); break;
      case 4: doMisuse(in, o); break;
      default: doLoad(in, o, flags & 1); return 0;
    }
  }
  return 0;
}
