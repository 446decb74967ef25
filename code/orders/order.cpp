#include "order.h"

#include <stdexcept>

namespace dt {

namespace {
constexpr InsertionOrder kOrders[] = {InsertionOrder::Brio, InsertionOrder::BrioDoubling,
                                      InsertionOrder::Hilbert, InsertionOrder::Input};
}  // namespace

const char* orderName(InsertionOrder order) {
  switch (order) {
    case InsertionOrder::Brio: return "brio";
    case InsertionOrder::BrioDoubling: return "brio-doubling";
    case InsertionOrder::Hilbert: return "hilbert";
    case InsertionOrder::Input: return "input";
  }
  throw std::invalid_argument("orderName: not an insertion order");
}

InsertionOrder orderNamed(const std::string& word) {
  for (InsertionOrder o : kOrders)
    if (word == orderName(o)) return o;
  throw std::invalid_argument("--order must be 'brio', 'brio-doubling', 'hilbert' or 'input'");
}

}  // namespace dt
