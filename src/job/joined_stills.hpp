// poster.png and contact_sheet.png of a joined render: the whole render's, byte for byte. The
// poster is the chunk's that drew the poster frame (scene::poster_frame falls in one chunk only);
// the contact sheet is composed again from the joined PNG frames by the sink a whole render uses
// (pipeline::ContactSheet), fed the frames it shows.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/result.hpp"
#include "job/join_inputs.hpp"

namespace tumble::job {

struct JoinedStills {
  bool poster = false;         // poster.png written
  bool contact_sheet = false;  // contact_sheet.png written
};

// Writes the stills into `staging`, whose frames/ holds the joined frames when the chunks have
// PNG frames (`chunks` sorted and checked). Without PNG frames there is no contact sheet: the
// videos' decoded pictures are not the frames' pixels.
Result<JoinedStills> write_joined_stills(const std::vector<ChunkReport>& chunks,
                                         const std::filesystem::path& staging);

}  // namespace tumble::job
