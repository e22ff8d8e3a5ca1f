// Sorting the edges of a plane graph by their first vertex without a comparison sort of them all:
// the validator and pieces_of sort millions of (vertex, vertex) pairs, and a vertex has few edges.
#pragma once

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace pd {

// Sorts `items` by operator<, given that items of different rows, row(item) < rows, order as their
// rows do: a stable counting sort by row, then each row's few items by a comparison sort. O(E + rows)
// and the rows' own sorts (a fan's row is sorted in O(d log d)).
template <class T, class Row>
void sort_in_rows(std::vector<T>& items, std::size_t rows, Row row) {
  std::vector<std::size_t> start(rows + 1, 0);
  for (const T& item : items) ++start[row(item) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<T> sorted(items.size());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const T& item : items) sorted[fill[row(item)]++] = item;
  for (std::size_t r = 0; r < rows; ++r)
    if (start[r + 1] - start[r] > 1)
      std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[r]), sorted.begin() + static_cast<std::ptrdiff_t>(start[r + 1]));
  items.swap(sorted);
}

}  // namespace pd
