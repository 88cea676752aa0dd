// libFuzzer harness: the LAS reader (io/LasHeader.cpp, io/LasReader.cpp: LAS 1.0-1.4, point formats 0-10),
// through io::openPointReader as stylos-cli and the workbench read a .las file, every batch to the end. Inputs
// of odd length are read in an import frame (+Y up, millimetres: the FramedReader).
#include "FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace stylos;
    core::io::ReadOptions options;
    if (size % 2 == 1) options.frame = {core::io::UpAxis::PosY, core::io::LengthUnit::Millimetre, {0.0, 0.0, 0.0}};
    fuzz::readAllPoints(fuzz::writeScratch(data, size, "las"), options);
    return 0;
}
