#pragma once
// Where each world of a side-by-side comparison is drawn (issue 24): the image split into panes,
// one per world, each seen through the scene's camera. With the overlay (or plots) shown, a
// column on the left holds the panel and the plots, and the panes share the rest, so no world
// is hidden behind the numbers.
#include <cstddef>
#include <vector>

#include "frame_data.h"

namespace rbsim::render {

// A pane in pixels from the image's top left.
struct PaneRect {
  int x = 0, y = 0, width = 0, height = 0;
};

// The overlay's margin from the image's edges [px]: grows with the image height.
float overlayMargin(int imageHeight);

// The left column kept for the panel and the plots [px]: the panel's width, plus its margins; a
// compact panel's column is narrower than a full one's.
int infoColumnWidth(int imageWidth, int imageHeight, PanelMode panel);

// `count` panes in a grid over the image (right of the info column when `infoColumn`): of the
// grids with room for all, the one whose panes' width/height is nearest the image's own (so the
// scene's camera, framed for the whole image, fits each pane), filled row by row; panes are
// separated by kPaneGap pixels.
std::vector<PaneRect> paneLayout(std::size_t count, int imageWidth, int imageHeight, bool infoColumn,
                                 PanelMode panel = PanelMode::Compact);

// The camera for a pane: the scene's, with a taller field of view when the pane is narrower than
// the image, so a pane shows at least the width the whole image would.
Camera paneCamera(const Camera& camera, int imageWidth, int imageHeight, const PaneRect& pane);

}  // namespace rbsim::render
