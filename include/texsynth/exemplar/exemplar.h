#pragma once
// The exemplar module: the analysis every synthesizer shares (Lefebvre & Hoppe 2005).
//   gaussian_stack.h    full-resolution Gaussian stack, spacing h_l per level
//   feature_distance.h  signed-distance feature channel from a binary mask
//   neighborhood.h      N x N neighborhood vectors at spacing h_l (gatherNeighborhood)
//   pca.h               PCA basis of neighborhoods and fast projection
//   similarity_sets.h   k-coherence similarity sets on nanoflann / FAISS
//   analysis.h          analyzeExemplar: all of the above per level
//   analysis_cache.h    analyzeExemplarCached: the same through a checked disk cache
#include "texsynth/exemplar/analysis.h"
#include "texsynth/exemplar/analysis_cache.h"
#include "texsynth/exemplar/feature_distance.h"
#include "texsynth/exemplar/gaussian_stack.h"
#include "texsynth/exemplar/neighborhood.h"
#include "texsynth/exemplar/pca.h"
#include "texsynth/exemplar/similarity_sets.h"
