#pragma once

namespace ptview {

// The order in which the compute backend's workgroups take the rows of an image. llvmpipe hands
// a dispatch's workgroups, numbered row by row, to its threads in contiguous runs of workgroups /
// threads each (Mesa's lp_cs_tpool.c). In row order, one of two threads would get the top of the
// image and the other the bottom, and where the costly part of a scene lies in one half (a mesh
// on the floor), one thread would work alone at the end of every pass. Workgroup row y therefore
// renders image row (y * stride) % rowCount (pathtrace.comp): with a stride coprime to rowCount
// every row is rendered once, and with one near rowCount times the golden ratio's fractional part
// any run of consecutive workgroups spreads over the whole image (docs/performance.md, issue 35).
// GPUs schedule workgroups as they go and need no such order; that they lose nothing by it (rows
// far apart running side by side share less of their cache) is not measured.
int workGroupRowStride(int rowCount);

} // namespace ptview
