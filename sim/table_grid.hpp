#pragma once
// Inside sim only: the whole level set built from the revolved table, for a stock whose grid
// was not built while the table held it.

#include "sim/stock_grid.hpp"

namespace lathesim::sim {

/// Builds `stock.grid` from `stock.table`: every voxel takes the value and active state the
/// table gives it (each leaf's image as settle() writes it, table_leaf_image.hpp), a uniform
/// leaf becomes a level-1 tile, a uniform 128³ block a level-2 tile, and air is left to the
/// background. Then the table's changes are forgotten: the grid is up to date with it.
/// Precondition: `stock.grid` holds only its background (an empty tree) and `stock.table` the
/// stock; std::logic_error otherwise.
void writeGridFromTable(StockGrid& stock);

}  // namespace lathesim::sim
