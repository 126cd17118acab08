// The law string of /CTCLAW (docs/theory/contact-laws.md section 4), e.g.
// n2s13{pz1e5,lambda2e3,Mu0.3,CtLin10}, read into a model::ContactLaw. A pure function of the text: no deck,
// no model. Every problem is collected, each naming the parameter at fault (or "law string") and what is
// accepted.
//
// Grammar (spaces ignored, names case-insensitive):
//   law    = [ "n" normal ] [ "s" friction ] [ "{" [ param { "," param } ] "}" ]
//   normal = 1 | 2 | 3 | 4;  friction = 1 | 2 | 3 | 4 | 11 | 12 | 13 | 14
//   param  = name [ "=" ] number  |  "kp" m "=" number   (m, the exponent of a power term, a number >= 1)
// numbers in C or Fortran form (1e5, 1.D5, .5, -1). At least one of n and s is given; without n the
// interface's own penalty stays the normal law, without s the contact is frictionless.
//
// Parameters: n1 Kc (> 0, or -1: automatic K / A_s); n2 pz (> 0), lambda (> 0) or pe (> 0), one of them,
// KcMax (> 0, optional; >= lambda pz when lambda is given); n3 CurveID (a /FUNCT id), Cubic (0 or 1,
// optional); n4 kp<m>=<value> (one or more, m >= 1 distinct, value >= 0, one of them > 0). Friction: Mu (>=
// 0) for every s law, CtLin (> 0) for s2..s4 and s12..s14 only, kappa (> 0, optional).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "solver/model/model.hpp"

namespace radx {

struct UrnProblem {
  std::string parameter;   // the parameter concerned ("KcMax", "kp2", a name as written), or "law string"
  std::string message;     // what is wrong and what is accepted
  std::size_t offset = 0;  // index into the text given to parse_ctclaw_urn of where the problem lies
};

struct UrnResult {
  // The law as read. Values are as written (deck input units); `law.curve` stays kNone: the /FUNCT id is
  // curve_id, resolved by the model builder.
  model::ContactLaw law;
  std::int64_t curve_id = 0;         // CurveID (n3), 0 when absent or bad
  std::size_t curve_offset = 0;      // where CurveID is written
  std::vector<UrnProblem> problems;  // empty: the law is valid
  [[nodiscard]] bool ok() const { return problems.empty(); }
};

UrnResult parse_ctclaw_urn(std::string_view text);

}  // namespace radx
