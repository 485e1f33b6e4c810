// Broadcasting of the core's functions over NumPy arrays, the way NumPy's generalized ufuncs do it.
//
// A binding is a C++ lambda over one element that calls the core (python/src/module.cpp). This
// header turns it into a Python function: it reads each argument as an array, checks its dtype
// and shape, broadcasts the arguments' leading ("loop") dimensions by NumPy's rules, runs the
// lambda on every element with the GIL released, and returns the fields of the core's result as
// arrays (a named tuple when there are several).
//
//  - Core dimensions: a scalar argument (double) takes an array of any shape; a vector (vec3) needs
//    a last dimension of 3, a frame a last two of (3, 3) (rows e1, e2, e3). Those dimensions
//    belong to one element; the others broadcast. Results add their own core dimensions last.
//  - Dtypes: an argument NumPy casts to float64 safely (numpy.can_cast(dtype, float64, "safe"):
//    float16/32/64, integers, bool) is converted; anything else (complex, object, strings,
//    datetime, long double) raises TypeError, since a silent conversion would drop a part or
//    round. A status argument takes integers only, each a status code (else ValueError).
//  - Shapes that do not broadcast, or a missing core dimension, raise ValueError naming the
//    function, the arguments and their shapes. Values are never refused: NaN, inf or an
//    out-of-range angle reach the core, which answers with its status (invalid), as from C++.
//  - Scalars in, NumPy scalars out (as a ufunc): a result with no dimensions is returned as a
//    NumPy scalar, not a 0-d array.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "conescan/conescan.hpp"

namespace conescan::python {

namespace py = pybind11;
using py::ssize_t;

/// A 3x3 matrix as NumPy holds it, row-major (m[row][col]): the Python form of a scan frame (rows
/// e1, e2, e3) and of a direction cosine matrix (m @ v = apply(C, v)).
struct matrix3 {
  double m[3][3];
};

/// The statuses' names, indexed by code: conescan.status_names, from the core's one list
/// (all_statuses, status.hpp).
inline py::tuple status_names() {
  py::list names;
  for (status s : all_statuses) names.append(to_string(s));
  return py::tuple(names);
}

// ---- Arguments: how one element is read ----------------------------------------------------

/// A value of the array's element type at p: memcpy, since NumPy may hand over unaligned data.
template <class Stored>
Stored load(const char* p) noexcept {
  Stored v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

/// What an argument of C++ type Arg takes from Python: its element type (the dtype the array is
/// converted to), its core dimensions (each of length 3) and how one element is read, given the
/// byte strides of the core dimensions.
template <class Arg>
struct argument;

template <>
struct argument<double> {
  using stored = double;
  static constexpr int core_ndim = 0;
  static double read(const char* p, const ssize_t*) noexcept { return load<double>(p); }
};

template <>
struct argument<vec3<double>> {
  using stored = double;
  static constexpr int core_ndim = 1;
  static vec3<double> read(const char* p, const ssize_t* core) noexcept {
    return vec3<double>(load<double>(p), load<double>(p + core[0]), load<double>(p + 2 * core[0]));
  }
};

/// A scan frame: rows e1, e2, e3 (each a unit vector in the common axes). Like the core, the
/// bindings do not check that the rows are orthonormal: pass a frame (scan_frame_from_mounting,
/// rotated as needed).
template <>
struct argument<scan_frame<double>> {
  using stored = double;
  static constexpr int core_ndim = 2;
  static scan_frame<double> read(const char* p, const ssize_t* core) noexcept {
    const vec3<double> e1 = argument<vec3<double>>::read(p, core + 1);
    const vec3<double> e2 = argument<vec3<double>>::read(p + core[0], core + 1);
    const vec3<double> e3 = argument<vec3<double>>::read(p + 2 * core[0], core + 1);
    return {e1, e2, e3, status::ok};
  }
};

/// A status code (an integer of conescan.status_names); checked before the loop.
template <>
struct argument<status> {
  using stored = std::int64_t;
  static constexpr int core_ndim = 0;
  static status read(const char* p, const ssize_t*) noexcept {
    return static_cast<status>(load<std::int64_t>(p));
  }
};

// ---- Results: how one element is written ---------------------------------------------------

/// How a field of C++ type V is stored: its dtype, its core shape and the write of element i
/// into a C-contiguous output.
template <class V>
struct output;

template <>
struct output<double> {
  using stored = double;
  static std::vector<ssize_t> core_shape() { return {}; }
  static void write(char* base, std::size_t i, double v) noexcept {
    reinterpret_cast<double*>(base)[i] = v;
  }
};

template <>
struct output<vec3<double>> {
  using stored = double;
  static std::vector<ssize_t> core_shape() { return {3}; }
  static void write(char* base, std::size_t i, const vec3<double>& v) noexcept {
    double* out = reinterpret_cast<double*>(base) + 3 * i;
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
  }
};

template <>
struct output<matrix3> {
  using stored = double;
  static std::vector<ssize_t> core_shape() { return {3, 3}; }
  static void write(char* base, std::size_t i, const matrix3& v) noexcept {
    std::memcpy(reinterpret_cast<double*>(base) + 9 * i, v.m, sizeof v.m);
  }
};

template <>
struct output<status> {
  using stored = std::uint8_t;  // the enum's own underlying type
  static std::vector<ssize_t> core_shape() { return {}; }
  static void write(char* base, std::size_t i, status v) noexcept {
    reinterpret_cast<std::uint8_t*>(base)[i] = static_cast<std::uint8_t>(v);
  }
};

template <>
struct output<int> {
  using stored = std::int32_t;
  static std::vector<ssize_t> core_shape() { return {}; }
  static void write(char* base, std::size_t i, int v) noexcept {
    reinterpret_cast<std::int32_t*>(base)[i] = static_cast<std::int32_t>(v);
  }
};

/// One field of a result: its Python name and how to get it from the C++ result (a member
/// pointer or a callable).
template <class Get>
struct field {
  const char* name;
  Get get;
};
template <class Get>
field(const char*, Get) -> field<Get>;

/// The fields of a core result type R, in Python's order, and the name of the named tuple that
/// holds them (python/src/results.hpp). A result with one field (type_name nullptr) is returned
/// as that field's array alone.
template <class R>
struct result_fields;

/// A plain value (double, vec3, matrix3): one array.
template <class V>
struct plain_result_fields {
  static constexpr const char* type_name = nullptr;
  static auto fields() {
    return std::make_tuple(field{"value", [](const V& v) { return v; }});
  }
};
template <>
struct result_fields<double> : plain_result_fields<double> {};
template <>
struct result_fields<vec3<double>> : plain_result_fields<vec3<double>> {};
template <>
struct result_fields<matrix3> : plain_result_fields<matrix3> {};

// ---- Shapes ------------------------------------------------------------------------------

/// A shape as Python prints a tuple: (), (3,), (4, 3).
inline std::string shape_text(const ssize_t* dims, ssize_t ndim) {
  std::string text = "(";
  for (ssize_t d = 0; d < ndim; ++d) {
    if (d > 0) text += ", ";
    text += std::to_string(dims[d]);
  }
  return text + (ndim == 1 ? ",)" : ")");
}

/// One argument, converted, with its loop dimensions' strides aligned to the broadcast shape.
struct operand {
  py::array array;  ///< the converted array; holds the data while the GIL is released
  std::vector<ssize_t> loop_shape;
  std::vector<ssize_t> loop_strides;  ///< bytes; 0 along a broadcast dimension
  std::array<ssize_t, 2> core_strides{};
};

/// str(obj) of any Python object.
inline std::string text(const py::handle& obj) {
  return py::str(obj).cast<std::string>();
}

/// The argument `obj` as an array of Stored, or TypeError when NumPy would not cast it safely.
template <class Stored>
py::array converted(const char* function, const char* name, const py::handle& obj) {
  const py::module_ numpy = py::module_::import("numpy");
  const py::array array = numpy.attr("asarray")(obj);
  const py::dtype target = py::dtype::of<Stored>();
  if (!numpy.attr("can_cast")(array.dtype(), target, "safe").template cast<bool>()) {
    const char* expected = std::is_same_v<Stored, double> ? "real numbers" : "status codes";
    throw py::type_error(std::string(function) + ": " + name + " has dtype " + text(array.dtype()) +
                         ", which numpy does not cast to " + text(target) + " safely (expected " +
                         expected + ")");
  }
  return py::array_t<Stored, py::array::forcecast>::ensure(array);
}

/// The status codes of a status argument, all in range, or ValueError naming the first that is
/// not.
inline void check_status_codes(const char* function, const char* name, const py::array& codes) {
  const py::module_ numpy = py::module_::import("numpy");
  const ssize_t count = static_cast<ssize_t>(py::len(status_names()));
  const py::array bad = numpy.attr("logical_or")(numpy.attr("less")(codes, 0),
                                                 numpy.attr("greater_equal")(codes, count));
  if (!numpy.attr("any")(bad).cast<bool>()) return;
  const py::object first = codes.attr("__getitem__")(bad).attr("flat")[py::int_(0)];
  throw py::value_error(std::string(function) + ": " + name + " holds " + text(first) +
                        ", which is not a status code (0 to " + std::to_string(count - 1) +
                        ", conescan.status_names)");
}

template <class Arg>
operand prepare(const char* function, const char* name, const py::handle& obj) {
  using spec = argument<Arg>;
  operand op;
  op.array = converted<typename spec::stored>(function, name, obj);
  const ssize_t ndim = op.array.ndim();
  const ssize_t loop_ndim = ndim - spec::core_ndim;
  bool core_ok = loop_ndim >= 0;
  for (ssize_t d = loop_ndim; core_ok && d < ndim; ++d) core_ok = op.array.shape(d) == 3;
  if (!core_ok) {
    const std::string wanted = spec::core_ndim == 1 ? "(..., 3)" : "(..., 3, 3)";
    throw py::value_error(std::string(function) + ": " + name + " must have shape " + wanted +
                          ", got " + shape_text(op.array.shape(), ndim));
  }
  if constexpr (std::is_same_v<Arg, status>) check_status_codes(function, name, op.array);
  op.loop_shape.assign(op.array.shape(), op.array.shape() + loop_ndim);
  op.loop_strides.assign(op.array.strides(), op.array.strides() + loop_ndim);
  for (int c = 0; c < spec::core_ndim; ++c) op.core_strides[c] = op.array.strides(loop_ndim + c);
  return op;
}

/// The broadcast of the operands' loop shapes (NumPy's rules: align on the right, a dimension of
/// 1 stretches), with each operand's strides aligned to it; ValueError when they do not fit.
template <std::size_t N>
std::vector<ssize_t> broadcast(const char* function, const std::array<const char*, N>& names,
                               std::array<operand, N>& ops) {
  std::size_t ndim = 0;
  for (const operand& op : ops) ndim = std::max(ndim, op.loop_shape.size());
  std::vector<ssize_t> shape(ndim, 1);
  bool fits = true;
  for (const operand& op : ops) {
    const std::size_t offset = ndim - op.loop_shape.size();
    for (std::size_t d = 0; d < op.loop_shape.size(); ++d) {
      const ssize_t size = op.loop_shape[d];
      ssize_t& common = shape[offset + d];
      if (common == 1)
        common = size;
      else if (size != 1 && size != common)
        fits = false;
    }
  }
  if (!fits) {
    std::string shapes;
    for (std::size_t i = 0; i < N; ++i) {
      shapes += i == 0 ? "" : (i + 1 == N ? " and " : ", ");
      shapes += std::string(names[i]) + " " + shape_text(ops[i].array.shape(), ops[i].array.ndim());
    }
    throw py::value_error(std::string(function) + ": the shapes of " + shapes +
                          " do not broadcast together");
  }
  for (operand& op : ops) {
    const std::size_t offset = ndim - op.loop_shape.size();
    std::vector<ssize_t> strides(ndim, 0);
    for (std::size_t d = 0; d < op.loop_shape.size(); ++d)
      if (op.loop_shape[d] != 1) strides[offset + d] = op.loop_strides[d];
    op.loop_strides = std::move(strides);
  }
  return shape;
}

// ---- The loop ------------------------------------------------------------------------------

/// Runs kernel(element...) over the broadcast shape in C order, handing each result to
/// store(result, flat index). Called with the GIL released: touches no Python object.
template <class... Args, class Kernel, class Store, std::size_t... I>
void run_loop(const Kernel& kernel, const Store& store, const std::vector<ssize_t>& shape,
              const std::array<operand, sizeof...(Args)>& ops, std::index_sequence<I...>) {
  constexpr std::size_t n = sizeof...(Args);
  for (const ssize_t size : shape)
    if (size == 0) return;
  const std::size_t ndim = shape.size();
  std::array<const char*, n> at{static_cast<const char*>(ops[I].array.data())...};
  std::array<const ssize_t*, n> core{ops[I].core_strides.data()...};
  // The last dimension runs in the inner loop; the others advance like an odometer.
  const ssize_t inner = ndim == 0 ? 1 : shape[ndim - 1];
  const std::array<ssize_t, n> inner_stride{(ndim == 0 ? 0 : ops[I].loop_strides[ndim - 1])...};
  std::vector<ssize_t> index(ndim, 0);
  std::size_t flat = 0;
  for (;;) {
    for (ssize_t j = 0; j < inner; ++j, ++flat)
      store(kernel(argument<Args>::read(at[I] + j * inner_stride[I], core[I])...), flat);
    std::size_t d = ndim < 2 ? 0 : ndim - 1;
    for (; d > 0; --d) {
      ((at[I] += ops[I].loop_strides[d - 1]), ...);
      if (++index[d - 1] < shape[d - 1]) break;
      ((at[I] -= ops[I].loop_strides[d - 1] * shape[d - 1]), ...);
      index[d - 1] = 0;
    }
    if (d == 0) return;
  }
}

/// The named-tuple type of result type R, made once by register_result_type. Never destroyed:
/// Python may be gone by the time static destructors run.
template <class R>
py::object& result_type() {
  static py::object* type = new py::object();
  return *type;
}

/// Makes R's named tuple (collections.namedtuple, fields in result_fields' order) and puts it on
/// the module under its type name, once; nothing for a plain result.
template <class R>
void register_result_type(py::module_& m) {
  if constexpr (result_fields<R>::type_name != nullptr) {
    py::object& type = result_type<R>();
    if (type) return;
    py::list names;
    std::apply([&](const auto&... f) { (names.append(f.name), ...); }, result_fields<R>::fields());
    type =
        py::module_::import("collections")
            .attr("namedtuple")(result_fields<R>::type_name, names, py::arg("module") = "conescan");
    m.attr(result_fields<R>::type_name) = type;
  }
}

/// An output array of the loop shape followed by the field's core shape.
template <class V>
py::array allocate(const std::vector<ssize_t>& loop_shape) {
  std::vector<ssize_t> shape = loop_shape;
  for (const ssize_t d : output<V>::core_shape()) shape.push_back(d);
  return py::array_t<typename output<V>::stored>(shape);
}

/// A result with no dimensions as a NumPy scalar (arr[()]), as a ufunc returns it.
inline py::object unwrapped(const py::array& array) {
  if (array.ndim() == 0) return array.attr("__getitem__")(py::tuple());
  return array;
}

template <class... Args, class Kernel, std::size_t... I>
py::object vectorized(const char* function, const std::array<const char*, sizeof...(Args)>& names,
                      const Kernel& kernel, const std::array<py::object, sizeof...(Args)>& objects,
                      std::index_sequence<I...> indices) {
  std::array<operand, sizeof...(Args)> ops{prepare<Args>(function, names[I], objects[I])...};
  const std::vector<ssize_t> shape = broadcast(function, names, ops);

  using R = std::decay_t<std::invoke_result_t<const Kernel&, Args...>>;
  const auto fields = result_fields<R>::fields();
  std::vector<py::array> arrays;
  std::apply(
      [&](const auto&... f) {
        (arrays.push_back(
             allocate<std::decay_t<std::invoke_result_t<decltype(f.get), const R&>>>(shape)),
         ...);
      },
      fields);
  std::vector<char*> bases;
  for (py::array& a : arrays) bases.push_back(static_cast<char*>(a.mutable_data()));
  const auto store = [&](const R& r, std::size_t flat) {
    std::size_t k = 0;
    std::apply(
        [&](const auto&... f) {
          ((output<std::decay_t<std::invoke_result_t<decltype(f.get), const R&>>>::write(
               bases[k++], flat, std::invoke(f.get, r))),
           ...);
        },
        fields);
  };
  {
    py::gil_scoped_release release;
    run_loop<Args...>(kernel, store, shape, ops, indices);
  }
  if constexpr (result_fields<R>::type_name == nullptr) {
    return unwrapped(arrays[0]);
  } else {
    py::tuple values(arrays.size());
    for (std::size_t k = 0; k < arrays.size(); ++k) values[k] = unwrapped(arrays[k]);
    return result_type<R>()(*values);
  }
}

// ---- Definition ----------------------------------------------------------------------------

template <class F>
struct signature : signature<decltype(&F::operator())> {};
template <class C, class R, class... A>
struct signature<R (C::*)(A...) const> {
  using arguments = std::tuple<std::decay_t<A>...>;
};
template <class C, class R, class... A>
struct signature<R (C::*)(A...) const noexcept> : signature<R (C::*)(A...) const> {};

template <class>
using as_object = py::object;

template <class Kernel, class... Args, class... Extra>
void define(py::module_& m, const char* function, const char* doc, Kernel kernel,
            std::tuple<Args...>, const Extra&... extra) {
  static_assert(sizeof...(Args) == sizeof...(Extra), "one py::arg per argument of the kernel");
  register_result_type<std::decay_t<std::invoke_result_t<const Kernel&, Args...>>>(m);
  const std::array<const char*, sizeof...(Args)> names{extra.name...};
  const std::string label = std::string("conescan.") + function;  // in error messages
  m.def(
      function,
      [label, names, kernel](as_object<Args>... objects) {
        return vectorized<Args...>(label.c_str(), names, kernel, {std::move(objects)...},
                                   std::index_sequence_for<Args...>{});
      },
      doc, extra...);
}

/// Defines m.function as the vectorised kernel: a lambda over one element (double, vec3<double>,
/// scan_frame<double> or status arguments) returning a core result with result_fields. One
/// py::arg per argument names it (and may give it a default).
template <class Kernel, class... Extra>
void def_vectorized(py::module_& m, const char* function, const char* doc, Kernel kernel,
                    const Extra&... extra) {
  define(m, function, doc, kernel, typename signature<Kernel>::arguments{}, extra...);
}

}  // namespace conescan::python
