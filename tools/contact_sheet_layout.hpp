// Where contact_sheet puts things, so the tests can find each tile.
#pragma once

namespace ocean_tools {

constexpr int kSheetMargin = 16, kSheetLabel = 40, kSheetTitle = 30;

// Top-left corner of row r, column c (0: rendered now, 1: the step's screenshot).
inline int sheet_tile_x(int column, int tile_width) { return kSheetMargin + column * (tile_width + kSheetMargin); }
inline int sheet_tile_y(int row, int tile_height) {
    return kSheetTitle + kSheetMargin + row * (tile_height + kSheetLabel + kSheetMargin);
}
inline int sheet_width(int tile_width) { return 2 * tile_width + 3 * kSheetMargin; }
inline int sheet_height(int rows, int tile_height) {
    return kSheetMargin + rows * (tile_height + kSheetLabel + kSheetMargin) + kSheetTitle;
}

}  // namespace ocean_tools
