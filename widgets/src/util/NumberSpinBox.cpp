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
    bool ok = false;
    double value = locale().toDouble(number, &ok);
    // A point is the decimal point where the locale's is another and the point separates no groups (French), and
    // in scientific notation always (2.5e-3 in Greek, whose group separator is the point).
    if (!ok && (number.contains(QLatin1Char('e'), Qt::CaseInsensitive) || locale().groupSeparator() != QLatin1String("."))) {
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
    if (const auto value = parse(number))
        // Out of range: kept as typed, not applied (the plain spin box refused the key that took it out of range,
        // so 720 became 72 and was applied).
        return *value >= minimum() && *value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
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
