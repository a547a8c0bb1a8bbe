// The health report as HTML and JSON, written through QSaveFile.
#include "healthreport.h"

#include "savefile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QLocale>

namespace {

struct HealthReportTr
{
    Q_DECLARE_TR_FUNCTIONS(HealthReport)
};

} // namespace

namespace feetech {

namespace {

QString escaped(const QString &text)
{
    return text.toHtmlEscaped();
}

QString measured(const std::optional<double> &value, int decimals, const QString &unit)
{
    return value ? QLocale().toString(*value, 'f', decimals) + QLatin1Char(' ') + unit
                 : HealthReportTr::tr("not read");
}

QString verdictColour(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Ok:
        return QStringLiteral("#1b7f3b");
    case Verdict::Warning:
        return QStringLiteral("#a86400");
    case Verdict::Fault:
        return QStringLiteral("#b3261e");
    }
    return {};
}

} // namespace

std::optional<ReportFormat> reportFormatFor(const QString &path)
{
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("html") || suffix == QLatin1String("htm"))
        return ReportFormat::Html;
    if (suffix == QLatin1String("json"))
        return ReportFormat::Json;
    return std::nullopt;
}

QByteArray healthReportJson(const HealthReport &report)
{
    const QJsonObject root {{QStringLiteral("format"), 1},
                            {QStringLiteral("port"), report.port},
                            {QStringLiteral("checked_at"), report.checkedAt.toString(Qt::ISODate)},
                            {QStringLiteral("servos"), healthJson(report.servos)}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QString healthReportHtml(const HealthReport &report)
{
    QString html;
    html += QStringLiteral("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%1</title>")
                .arg(escaped(HealthReportTr::tr("Servo health report")));
    html += QStringLiteral(
        "<style>body{font-family:sans-serif}table{border-collapse:collapse}"
        "td,th{border:1px solid #999;padding:4px 8px;vertical-align:top;text-align:left}"
        "</style></head><body>\n");
    html += QStringLiteral("<h1>%1</h1>\n<p>%2</p>\n")
                .arg(escaped(HealthReportTr::tr("Servo health report")),
                     escaped(HealthReportTr::tr("Port %1, checked %2")
                                 .arg(report.port,
                                      QLocale().toString(report.checkedAt, QLocale::LongFormat))));
    if (report.servos.isEmpty()) {
        html +=
            QStringLiteral("<p>%1</p>\n").arg(escaped(HealthReportTr::tr("No servo was checked.")));
    } else {
        html += QStringLiteral("<table>\n<tr>");
        for (const QString &heading :
             {HealthReportTr::tr("ID"), HealthReportTr::tr("Model"), HealthReportTr::tr("Firmware"),
              HealthReportTr::tr("Verdict"), HealthReportTr::tr("Voltage"),
              HealthReportTr::tr("Temperature"), HealthReportTr::tr("Load"),
              HealthReportTr::tr("Status"), HealthReportTr::tr("Communication"),
              HealthReportTr::tr("Move test"), HealthReportTr::tr("Reasons")})
            html += QStringLiteral("<th>%1</th>").arg(escaped(heading));
        html += QStringLiteral("</tr>\n");
        for (const ServoHealth &servo : report.servos) {
            QStringList reasons;
            for (const HealthFinding &finding : servo.findings)
                reasons.append(QStringLiteral("<li><code>%1</code> %2</li>")
                                   .arg(escaped(finding.code), escaped(finding.message)));
            const QStringList cells {
                QString::number(servo.id),
                escaped(servo.model),
                escaped(servo.firmware),
                QStringLiteral("<b style=\"color:%1\">%2</b>")
                    .arg(verdictColour(servo.verdict), escaped(verdictName(servo.verdict))),
                escaped(measured(servo.voltage, 1, QStringLiteral("V"))),
                escaped(measured(servo.temperature, 0, QStringLiteral("°C"))),
                escaped(measured(servo.load, 1, QStringLiteral("%"))),
                escaped(servo.statusText),
                escaped(commText(servo.comm)),
                escaped(servo.move ? moveText(*servo.move) : HealthReportTr::tr("not run")),
                reasons.isEmpty() ? escaped(HealthReportTr::tr("none"))
                                  : QStringLiteral("<ul>%1</ul>").arg(reasons.join(QString()))};
            html += QStringLiteral("<tr>");
            for (const QString &cell : cells)
                html += QStringLiteral("<td>%1</td>").arg(cell);
            html += QStringLiteral("</tr>\n");
        }
        html += QStringLiteral("</table>\n");
    }
    html += QStringLiteral("</body></html>\n");
    return html;
}

bool saveHealthReport(const QString &path, ReportFormat format, const HealthReport &report,
                      QString *error)
{
    const auto fail = [&](const QString &reason) {
        if (error)
            *error = HealthReportTr::tr("The report could not be saved to %1: %2")
                         .arg(QDir::toNativeSeparators(path), reason);
        return false;
    };
    util::SavingFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(file.errorString());
    const QByteArray bytes =
        format == ReportFormat::Json ? healthReportJson(report) : healthReportHtml(report).toUtf8();
    if (file.device().write(bytes) != bytes.size())
        return fail(file.errorString());
    if (!file.commit())
        return fail(file.errorString());
    return true;
}

} // namespace feetech
