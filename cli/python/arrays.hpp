#pragma once
// numpy views of madd's result vectors (docs/python.md, "Results"): no copy.
// A view's memory belongs to the Python object that holds the C++ result
// (its `base`), so the array keeps that object alive; views are read-only,
// since the result is a value the writers and checks read as it was made.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "madd/geometry.hpp"

namespace madd::python {

namespace py = pybind11;

// A read-only array of `T` over `data`: shape and strides (in bytes) as given.
template <class T>
py::array read_only_view(py::handle owner, const void* data, std::vector<py::ssize_t> shape,
                         std::vector<py::ssize_t> strides) {
  py::array view(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

// (n, 2) float64 over a vector of points.
inline py::array points_view(py::handle owner, const std::vector<Point>& points) {
  static_assert(sizeof(Point) == 2 * sizeof(double));
  return read_only_view<double>(owner, points.data(), {static_cast<py::ssize_t>(points.size()), 2},
                                {sizeof(Point), sizeof(double)});
}

// (n, k) int32 over the first k 32-bit fields of each element of `items`
// (index triples, or the endpoints of a segment record). Indices below 2^31
// read the same as int32; madd's "no index" (2^32 - 1) reads as -1.
template <class Item>
py::array index_view(py::handle owner, const std::vector<Item>& items, py::ssize_t k, std::size_t offset = 0) {
  return read_only_view<std::int32_t>(owner, reinterpret_cast<const char*>(items.data()) + offset,
                                      {static_cast<py::ssize_t>(items.size()), k},
                                      {sizeof(Item), sizeof(std::int32_t)});
}

// (n,) over one field of each element of `items`, at byte `offset`.
template <class T, class Item>
py::array field_view(py::handle owner, const std::vector<Item>& items, std::size_t offset) {
  return read_only_view<T>(owner, reinterpret_cast<const char*>(items.data()) + offset,
                           {static_cast<py::ssize_t>(items.size())}, {sizeof(Item)});
}

// (n,) over a vector of numbers.
template <class T, class Stored = T>
py::array vector_view(py::handle owner, const std::vector<Stored>& values) {
  static_assert(sizeof(T) == sizeof(Stored));
  return read_only_view<T>(owner, values.data(), {static_cast<py::ssize_t>(values.size())}, {sizeof(Stored)});
}

// The rows of an (n, 2) array-like of numbers, as points (BadInput naming
// `what` when it has another shape or a value is not finite is the caller's:
// this only converts).
std::vector<Point> to_points(py::handle array_like, const char* what);

}  // namespace madd::python
