#ifndef slPointDeduplication_h
#define slPointDeduplication_h
/**
 * @file slPointDeduplication.h
 * @brief Which rows of a table are byte-for-byte repeats of an earlier one:
 * the rule by which OBJ points equal in position and in every point value
 * are merged (slMergeIdenticalPoints, slParseOBJ). VTK-free. Internal to
 * ShadeLab::IO.
 */

#include "slMeshArrays.h"

#include <cstddef>
#include <cstdint>
#include <vector>

/// For @p count rows of @p rowBytes bytes each at @p rows: fills @p newId
/// with each row's index among the distinct rows (numbered in order of first
/// occurrence) and returns the index of each distinct row's first occurrence.
std::vector<std::int64_t> slUniqueRows(
  const unsigned char* rows, std::size_t rowBytes, std::size_t count, std::vector<std::int64_t>& newId);

/// Merges the points of @p mesh equal in position, normal, texture
/// coordinate and @p keys (a value per point, or empty), bit for bit,
/// keeping first occurrences in order, and renames the connectivity and
/// thins @p keys accordingly. @p mesh must have no colours, which this
/// neither compares nor thins: only OBJ meshes are merged, and the OBJ
/// parser gives none.
void slDeduplicatePoints(slMeshArrays& mesh, std::vector<std::int32_t>& keys);

#endif
