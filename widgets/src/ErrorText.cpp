#include "stylos/widgets/ErrorText.h"

#include <QFileInfo>

namespace stylos::widgets {

QString ErrorText::title(core::ErrorCode code)
{
    using core::ErrorCode;
    switch (code) {
    case ErrorCode::NotFound: return tr("The file does not exist");
    case ErrorCode::Unreadable: return tr("The file cannot be read");
    case ErrorCode::UnknownFormat: return tr("The file format is not recognised");
    case ErrorCode::Unsupported: return tr("This format is not supported");
    case ErrorCode::Malformed: return tr("The file is malformed");
    case ErrorCode::Truncated: return tr("The file is truncated");
    case ErrorCode::Empty: return tr("The file is empty");
    case ErrorCode::WriteFailed: return tr("The output could not be written");
    case ErrorCode::InvalidArgument: return tr("A parameter is out of range");
    case ErrorCode::OutOfBudget: return tr("Not enough memory for this operation");
    case ErrorCode::Cancelled: return tr("Cancelled");
    }
    return tr("Unknown error");
}

QString ErrorText::loadFailure(const QString& path, const core::Error& error)
{
    const QString name = QFileInfo(path).fileName();
    return tr("Could not load %1: %2.").arg(name, title(error.code)) + QLatin1Char('\n') +
           QString::fromStdString(error.message);
}

} // namespace stylos::widgets
