// The "periodic-packing" certificate of `superpack simulate` and `superpack md`: the exact configuration proved by
// problems/periodic/periodic_packing.hpp, with one separating normal per close pair; the checker
// (checker/claims/claim_periodic_packing.cpp) enumerates the close pairs itself and replays each plane.
#pragma once
#include "superpack/cert/certificate.hpp"
#include "superpack/problems/periodic/periodic_packing.hpp"

namespace superpack {

// Requires a proved certification (std::runtime_error otherwise). `command` ("simulate" or "md")
// is the certificate's "command": the command that wrote it.
template <class Field>
Json periodic_certificate(const PeriodicCertificate<typename Field::Interval>& proved, const Field& field, long digits,
                          const std::string& command);

// The configuration as JSON: cell rows, and per particle its centre and quaternion, exact.
Json periodic_packing_json(const PeriodicPacking& packing);

}  // namespace superpack
