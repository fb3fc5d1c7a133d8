// NumPy arrays over ensil's buffers: read-only views that keep their owner alive (no copy), and
// copies where the values must be converted. Called with the GIL held.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace ensil::python {

// A read-only view of `count` values at `data` with the given shape and strides (in bytes);
// `owner` keeps the memory alive as long as the array lives.
template <typename T>
pybind11::array_t<T> readOnlyView(const T* data, std::vector<pybind11::ssize_t> shape,
                                  std::vector<pybind11::ssize_t> strides,
                                  const pybind11::handle& owner) {
    pybind11::array_t<T> array(std::move(shape), std::move(strides), data, owner);
    array.attr("setflags")(pybind11::arg("write") = false);
    return array;
}

// A fresh 1-D array holding `values`, converted to T.
template <typename T, typename U>
pybind11::array_t<T> copyOf(const std::vector<U>& values) {
    pybind11::array_t<T> array(static_cast<pybind11::ssize_t>(values.size()));
    auto out = array.template mutable_unchecked<1>();
    for (std::size_t i = 0; i < values.size(); ++i) {
        out(static_cast<pybind11::ssize_t>(i)) = static_cast<T>(values[i]);
    }
    return array;
}

}  // namespace ensil::python
