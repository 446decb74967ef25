// The one vocabulary of insertion orders (section 2.3.5): the library, the command line and the
// chapter programs name an order with this enum, and read or write it with these words.
#pragma once

#include <string>

namespace dt {

/// Insertion order. One meaning each, whatever the kernel:
enum class InsertionOrder {
  Brio,          ///< "brio": dt::brioCoinOrder (hilbert.h), 8 BRIO rounds drawn by biased coins,
                 ///< each Hilbert-sorted (the default: no input makes its walks grow)
  BrioDoubling,  ///< "brio-doubling": dt::brioOrder, BRIO rounds of doubling sizes
  Hilbert,       ///< "hilbert": dt::hilbertOrder, one Hilbert sort (quadratic on points along a curve)
  Input          ///< "input": the order of the input (walks grow like sqrt(n); like n on sorted input)
};

/// The word of an order ("brio", "brio-doubling", "hilbert", "input").
const char* orderName(InsertionOrder order);

/// The order of a word of orderName; throws std::invalid_argument naming the words otherwise.
InsertionOrder orderNamed(const std::string& word);

}  // namespace dt
