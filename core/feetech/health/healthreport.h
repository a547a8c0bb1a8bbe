// The health check's report: the verdicts as a self-contained HTML page or as JSON, saved
// atomically.
#pragma once

#include "servohealth.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>
#include <QVector>

#include <optional>

namespace feetech {

enum class ReportFormat { Html, Json };

// By the file's suffix (.html, .htm, .json, any case); nothing for another.
std::optional<ReportFormat> reportFormatFor(const QString &path);

struct HealthReport
{
    QString port;
    QDateTime checkedAt;
    QVector<ServoHealth> servos;
};

// {"format": 1, "port", "checked_at", "servos": [healthJson of each]}
QByteArray healthReportJson(const HealthReport &report);
// One table row per servo, the verdict coloured, every text escaped; no outside resources.
QString healthReportHtml(const HealthReport &report);

// Writes the report through QSaveFile (a failed save leaves an existing file as it was).
// False and *error, naming the file and the reason, when it could not be written.
bool saveHealthReport(const QString &path, ReportFormat format, const HealthReport &report,
                      QString *error);

} // namespace feetech
