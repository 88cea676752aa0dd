#include "document/NumberSpinBox.h"

#include <QLocale>
#include <QRegularExpression>

namespace stylos::widgets {

std::optional<double> NumberSpinBox::scientific(const QString& text, bool* partial) const
{
    *partial = false;
    QString number = text;
    if (!prefix().isEmpty() && number.startsWith(prefix())) number.remove(0, prefix().size());
    if (!suffix().isEmpty() && number.endsWith(suffix())) number.chop(suffix().size());
    number = number.trimmed();
    if (!number.contains(QLatin1Char('e'), Qt::CaseInsensitive)) return std::nullopt;
    bool ok = false;
    const double value = locale().toDouble(number, &ok);
    if (ok) return value;
    // What may still become a number as the user types: a mantissa and an exponent mark, with or without
    // its sign ("1e", "2,5E-").
    const QString point = QRegularExpression::escape(locale().decimalPoint());
    const QRegularExpression started(QStringLiteral("^[+-]?([0-9]+(%1[0-9]*)?|%1[0-9]+)[eE][+-]?$").arg(point));
    *partial = started.match(number).hasMatch();
    return std::nullopt;
}

QValidator::State NumberSpinBox::validate(QString& text, int& pos) const
{
    bool partial = false;
    if (const auto value = scientific(text, &partial))
        return *value >= minimum() && *value <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    if (partial) return QValidator::Intermediate;
    return QDoubleSpinBox::validate(text, pos);
}

double NumberSpinBox::valueFromText(const QString& text) const
{
    bool partial = false;
    if (const auto value = scientific(text, &partial)) return *value;
    return QDoubleSpinBox::valueFromText(text);
}

} // namespace stylos::widgets
