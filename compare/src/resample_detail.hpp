//! @file Internals shared by the resampling drivers (not part of the public API).
#pragma once
#include <string>
#include <vector>

#include "hvi/compare/resample.hpp"

namespace hvi::compare::detail {

Resampled resampleParticles(const Snapshot& s, const GridSpec& grid, const ResampleOptions& opt);
Resampled resampleGrid(const Snapshot& s, const GridSpec& grid, const ResampleOptions& opt);

//! The scalar field `name` with one value per particle or cell; throws InputError otherwise.
const Field& requireField(const Snapshot& s, const std::string& name);

//! `given` extended with "<prefix><i>" so that every id in `ids` (>= 0) has a name.
std::vector<std::string> classNames(const std::vector<std::string>& given,
                                    const std::vector<double>* ids, const std::string& prefix);

//! Fills the empty result fields of `grid` (all vacuum) and copies the snapshot's metadata.
Resampled emptyResult(const Snapshot& s, const GridSpec& grid);

}  // namespace hvi::compare::detail
