// The errors every blockfrag library throws: one hierarchy, three kinds, so that each caller can
// tell the user's fault from the simulation's limits and from a bug.
//   InvalidInput       an input breaks a documented rule (a scene value outside its domain, a
//                      malformed config or record): refused with a message that names the value.
//   SimulationFailure  a valid scene the engine could not finish (a step or event budget spent, no
//                      consistent contact state, a step size the time axis cannot resolve): it
//                      becomes that scene's status, and a study's sample is "failed".
//   ContractViolation  a broken internal contract (a caller handing a function what its contract
//                      excludes): a bug, never turned into a sample's status; a study stops.
//   FileFailure        a file the program must read or write cannot be (permissions, a full disk,
//                      a damaged HDF5 file): the environment's fault, not the input's.
#pragma once

#include <stdexcept>
#include <string>

namespace blockfrag {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InvalidInput : public Error {
 public:
  using Error::Error;
};

class SimulationFailure : public Error {
 public:
  using Error::Error;
};

class ContractViolation : public Error {
 public:
  using Error::Error;
};

class FileFailure : public Error {
 public:
  using Error::Error;
};

}  // namespace blockfrag
