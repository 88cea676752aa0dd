#include "stylos/widgets/util/NumberSpinBox.h"

#include "stylos/widgets/util/WheelGuard.h"

#include <QLocale>
#include <QRegularExpression>

#include <cmath>

namespace stylos::widgets {

NumberSpinBox::NumberSpinBox(QWidget* parent) : QDoubleSpinBox(parent)
{
    // A value is applied on Enter or on leaving the field, never a prefix of what is being typed ("1e1" of "1e12").
    setKeyboardTracking(false);
    guardWheel(this);
}

QString NumberSpinBox::numberPart(const QString& text) const
{
    QString number = text;
    if (!prefix().isEmpty() && number.startsWith(prefix())) number.remove(0, prefix().size());
    if (!suffix().isEmpty() && number.endsWith(suffix())) number.chop(suffix().size());
    return number.trimmed();
}

std::optional<double> NumberSpinBox::parse(const QString& number) const
{
    // Group separators are never read (the boxes never show them): in Greek, whose group separator is the point,
    // "1.5" was read as 15. So a point is a decimal point in every language, as the locale's own is.
    QLocale local = locale();
    local.setNumberOptions(local.numberOptions() | QLocale::RejectGroupSeparator);
    bool ok = false;
    double value = local.toDouble(number, &ok);
    if (!ok) {
        QLocale c = QLocale::c();
        c.setNumberOptions(QLocale::RejectGroupSeparator);
        value = c.toDouble(number, &ok);
    }
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

QValidator::State NumberSpinBox::validate(QString& text, int& pos) const
{
    const QString number = numberPart(text);
    if (const auto value = parse(number)) {
        // Out of range: kept as typed, not applied (the plain spin box refused the key that took it out of range,
        // so 720 became 72 and was applied).
        if (*value < minimum() || *value > maximum()) return QValidator::Intermediate;
        // A value that the box's decimals round to its special value ("Automatic" for 0): not that (1e-3 mm in a
        // box of 0.01 mm became Automatic).
        const double unit = std::pow(10.0, decimals());
        if (!specialValueText().isEmpty() && *value != minimum() && std::round(*value * unit) / unit == minimum())
            return QValidator::Intermediate;
        return QValidator::Acceptable;
    }
    // What may still become a number as it is typed: "-", "2.", ",5", "1e", "2,5E-".
    const QString point = QRegularExpression::escape(locale().decimalPoint());
    const QRegularExpression started(QStringLiteral("^[+-]?[0-9]*((%1|\\.)[0-9]*)?([eE][+-]?[0-9]*)?$").arg(point));
    if (started.match(number).hasMatch()) return QValidator::Intermediate;
    return QDoubleSpinBox::validate(text, pos);
}

double NumberSpinBox::valueFromText(const QString& text) const
{
    if (const auto value = parse(numberPart(text))) return *value;
    return QDoubleSpinBox::valueFromText(text);
}

} // namespace stylos::widgets
