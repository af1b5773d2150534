// SPDX-License-Identifier: GPL-3.0-or-later
// Typed exceptions thrown by the core. Messages say what went wrong and where (which function,
// vertex, face, edge); the CLI prints them as one line, the plugin as MeshLab's error message.
#pragma once

#include <stdexcept>
#include <string>

namespace elastica {

/// Base class of every error the core throws.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The input mesh or a parameter cannot be processed (bad index, non-manifold edge, ...).
class InvalidInputError : public Error {
 public:
  using Error::Error;
};

/// A computation produced a non-finite value or could not proceed numerically.
class NumericalError : public Error {
 public:
  using Error::Error;
};

/// A file could not be read or written (missing, unreadable, malformed, unwritable ...).
/// The message starts with the file name.
class IoError : public Error {
 public:
  using Error::Error;
};

}  // namespace elastica
