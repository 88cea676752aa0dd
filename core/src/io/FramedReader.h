#pragma once
// A reader that hands out another reader's points in an import frame (ImportFrame.h: offset, unit, up
// axis), positions and normals alike; its header, counters and scans follow the wrapped reader's (the
// header's declared bounds mapped too; the scans' poses stay in the file's frame). openPointReader()
// wraps every reader in one when ReadOptions::frame is not the identity: the one place the frame is
// applied, so every command and the workbench read the corrected points.
#include "stylos/core/io/ImportFrame.h"
#include "stylos/core/io/PointReader.h"

#include <memory>

namespace stylos::core::io {

class FramedReader final : public PointReader {
public:
    FramedReader(std::unique_ptr<PointReader> inner, const ImportFrame& frame);

    Result<std::size_t> read(PointBatch& batch, std::size_t maxPoints) override;
    std::uint64_t bytesConsumed() const override { return m_inner->bytesConsumed(); }

private:
    /** Copies the wrapped reader's header, counters and scans (they change as it reads). */
    void follow();

    std::unique_ptr<PointReader> m_inner;
    ImportFrame m_frame;
};

} // namespace stylos::core::io
