// SPDX-License-Identifier: GPL-3.0-or-later
// Every enumerated option by name: the one table that maps a command-line word, a MeshLab menu
// entry and a report's word to a core enum value. The CLI builds its --flow/--scheme/... choices
// from it, the filters their RichEnum menus (whose index order is the .mlx value, fixed forever:
// append only), and the reports their words. Nothing converts an enum by its number.
#pragma once

#include <elastica/curvature.h>
#include <elastica/flow.h>
#include <elastica/geometry.h>
#include <elastica/hole_filling.h>

#include <map>
#include <string>
#include <vector>

namespace elastica::app {

template <class E>
struct Choice {
  E value;
  const char* name;   ///< command line and reports: "semi-implicit", "max_steps"
  const char* label;  ///< MeshLab's menu entry, or the sentence a log line uses
};

/// The table of E, in .mlx index order.
template <class E>
const std::vector<Choice<E>>& choices();

template <> const std::vector<Choice<FlowType>>& choices<FlowType>();
template <> const std::vector<Choice<Scheme>>& choices<Scheme>();
template <> const std::vector<Choice<BoundaryMode>>& choices<BoundaryMode>();
template <> const std::vector<Choice<H2KTreatment>>& choices<H2KTreatment>();
template <> const std::vector<Choice<VertexArea>>& choices<VertexArea>();
template <> const std::vector<Choice<FillStage>>& choices<FillStage>();
template <> const std::vector<Choice<StopReason>>& choices<StopReason>();

template <class E>
const Choice<E>& choiceOf(E value) {
  for (const Choice<E>& c : choices<E>())
    if (c.value == value) return c;
  return choices<E>().front();  // unreachable: every enumerator is in its table (tested)
}
/// The .mlx index of `value` (its position in the table).
template <class E>
int indexOf(E value) {
  const std::vector<Choice<E>>& t = choices<E>();
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i].value == value) return static_cast<int>(i);
  return 0;  // unreachable: every enumerator is in its table (tested)
}
/// The command-line / report word of `value`.
template <class E>
const char* nameOf(E value) { return choiceOf(value).name; }
/// The menu entry or log sentence of `value`.
template <class E>
const char* labelOf(E value) { return choiceOf(value).label; }

/// name -> value, for CLI11's CheckedTransformer.
template <class E>
std::map<std::string, E> nameMap() {
  std::map<std::string, E> m;
  for (const Choice<E>& c : choices<E>()) m.emplace(c.name, c.value);
  return m;
}

/// The menu entries in index order (a RichEnum's list).
template <class E>
std::vector<std::string> labels() {
  std::vector<std::string> l;
  for (const Choice<E>& c : choices<E>()) l.emplace_back(c.label);
  return l;
}

}  // namespace elastica::app
