// libFuzzer harness: the PTX reader (io/PtxReader.cpp: several scans, each with its 4x4 transform), through
// io::openPointReader as stylos-cli and the workbench read a .ptx file, every batch to the end. Inputs of odd
// length are read in an import frame (+Y up, millimetres: the FramedReader) and only scan 0.
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos;
    core::io::ReadOptions options;
    if (size % 2 == 1) {
        options.frame = {core::io::UpAxis::PosY, core::io::LengthUnit::Millimetre, {0.0, 0.0, 0.0}};
        options.scan = 0;
    }
    fuzz::readAllPoints(fuzz::writeScratch(data, size, "ptx"), options);
    return 0;
}
