// bench_report TARGETS RESULTS: one Markdown table of the benchmark figures in RESULTS (one
// <program>.json per program, as bench/run-all saves them) against the targets in TARGETS
// (bench/targets.json). Exit 0 when every measured figure meets its target, 1 when one does not
// or is missing (a GUI figure measured on another platform than its target names counts as
// missing), 2 when the targets file cannot be read.
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <optional>

namespace {

struct Lookup
{
    std::optional<double> value;
    QString problem; // why there is no value
};

class Results
{
public:
    explicit Results(const QString &folder)
        : m_folder(folder)
    { }

    // The number at `path` ("a.b.0.c": keys, and indexes into arrays) in <program>.json.
    Lookup number(const QString &program, const QString &path)
    {
        const QJsonDocument &document = load(program);
        if (document.isNull())
            return {std::nullopt, QStringLiteral("no %1.json").arg(program)};
        QJsonValue value =
            document.isArray() ? QJsonValue(document.array()) : QJsonValue(document.object());
        for (const QString &key : path.split(u'.')) {
            bool isIndex = false;
            const int index = key.toInt(&isIndex);
            value = value.isArray() && isIndex ? value.toArray().at(index)
                                               : value.toObject().value(key);
        }
        if (!value.isDouble())
            return {std::nullopt, QStringLiteral("no %1 in %2.json").arg(path, program)};
        return {value.toDouble(), {}};
    }

    // The text at top-level `key` of <program>.json; empty when there is none.
    QString text(const QString &program, const QString &key)
    {
        return load(program).object().value(key).toString();
    }

private:
    const QJsonDocument &load(const QString &program)
    {
        if (!m_documents.contains(program)) {
            QFile file(QDir(m_folder).filePath(program + QStringLiteral(".json")));
            QJsonDocument document;
            if (file.open(QIODevice::ReadOnly))
                document = QJsonDocument::fromJson(file.readAll());
            m_documents.insert(program, document);
        }
        return m_documents[program];
    }

    QString m_folder;
    QHash<QString, QJsonDocument> m_documents;
};

// Whole numbers as they are; others with three significant figures at most, never an exponent:
// 0.123, 1.23, 12.3, 123, 1234.
QString number(double value)
{
    if (value == std::floor(value) && std::fabs(value) < 1e15)
        return QString::number(qint64(value)); // counts stay counts
    const double magnitude = std::fabs(value);
    const int decimals = magnitude >= 100 ? 0 : magnitude >= 10 ? 1 : magnitude >= 1 ? 2 : 3;
    return QString::number(value, 'f', decimals);
}

QString withUnit(const QString &text, const QString &unit)
{
    return unit.isEmpty() ? text : text + u' ' + unit;
}

enum class Verdict { Met, NotMet, Missing, Elsewhere, Reference };

struct Row
{
    QString figure;
    QString measured;
    QString target;
    QString wire;
    Verdict verdict = Verdict::Missing;
};

Row evaluate(const QJsonObject &entry, Results &results)
{
    Row row;
    row.figure = entry.value(QStringLiteral("figure")).toString();
    const QString unit = entry.value(QStringLiteral("unit")).toString();
    const QString compare = entry.value(QStringLiteral("compare")).toString();
    // A figure without a target is printed for reference: it is neither met nor missed.
    const bool reference = !entry.contains(QStringLiteral("target"));
    const double target = entry.value(QStringLiteral("target")).toDouble();
    const bool relative = entry.value(QStringLiteral("relative_to_wire")).toBool();
    const QString sign = compare == QLatin1String(">=") ? QStringLiteral("≥") : QStringLiteral("≤");
    row.target = reference ? QStringLiteral("none (for reference)")
                           : sign + u' '
            + (relative ? QString::number(target) + QStringLiteral(" × wire")
                        : withUnit(QString::number(target), unit));

    const QJsonObject wire = entry.value(QStringLiteral("wire")).toObject();
    std::optional<double> wireValue;
    if (wire.contains(QStringLiteral("value"))) {
        const QString program = wire.value(QStringLiteral("program"))
                                    .toString(entry.value(QStringLiteral("program")).toString());
        const Lookup lookup =
            results.number(program, wire.value(QStringLiteral("value")).toString());
        wireValue = lookup.value;
        row.wire = lookup.value ? withUnit(number(*lookup.value), unit)
                                : QStringLiteral("missing (%1)").arg(lookup.problem);
        if (wire.contains(QStringLiteral("text")))
            row.wire += u' ' + wire.value(QStringLiteral("text")).toString();
    } else {
        row.wire = wire.value(QStringLiteral("text")).toString(QStringLiteral("—"));
    }

    const QString elsewhere = entry.value(QStringLiteral("measured_separately")).toString();
    if (!elsewhere.isEmpty()) {
        row.measured = QStringLiteral("not by run-all: ") + elsewhere;
        row.verdict = Verdict::Elsewhere;
        return row;
    }
    const Lookup measured = results.number(entry.value(QStringLiteral("program")).toString(),
                                           entry.value(QStringLiteral("value")).toString());
    if (!measured.value) {
        row.measured = QStringLiteral("missing (%1)").arg(measured.problem);
        return row;
    }
    // A GUI figure counts only from the display it names: Qt's offscreen platform draws nothing,
    // so its CPU and start-up times are not what a user sees.
    const QString platform = entry.value(QStringLiteral("platform")).toString();
    if (!platform.isEmpty()) {
        const QString used = results.text(entry.value(QStringLiteral("program")).toString(),
                                          QStringLiteral("platform"));
        if (used != platform) {
            row.measured =
                QStringLiteral("%1, not counted: measured on %2, not on %3")
                    .arg(withUnit(number(*measured.value), unit),
                         used.isEmpty() ? QStringLiteral("an unnamed platform") : used, platform);
            return row;
        }
    }
    double compared = *measured.value;
    row.measured = withUnit(number(compared), unit);
    if (relative) {
        if (!wireValue || *wireValue <= 0) {
            row.measured += QStringLiteral(" (no wire figure to compare with)");
            return row;
        }
        compared /= *wireValue;
        row.measured += QStringLiteral(" = %1 × wire").arg(number(compared));
    }
    if (reference) {
        row.verdict = Verdict::Reference;
        return row;
    }
    const bool met = compare == QLatin1String(">=") ? compared >= target : compared <= target;
    row.verdict = met ? Verdict::Met : Verdict::NotMet;
    return row;
}

QString verdictText(Verdict verdict)
{
    switch (verdict) {
    case Verdict::Met:
        return QStringLiteral("yes");
    case Verdict::NotMet:
        return QStringLiteral("**NO**");
    case Verdict::Missing:
        return QStringLiteral("**missing**");
    case Verdict::Elsewhere:
    case Verdict::Reference:
        break;
    }
    return QStringLiteral("—");
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList arguments = QCoreApplication::arguments();
    if (arguments.size() != 3) {
        std::fprintf(stderr, "usage: bench_report TARGETS.json RESULTS_FOLDER\n");
        return 2;
    }
    QFile targetsFile(arguments.at(1));
    if (!targetsFile.open(QIODevice::ReadOnly)) {
        std::fprintf(stderr, "bench_report: cannot read %s\n", qPrintable(arguments.at(1)));
        return 2;
    }
    QJsonParseError error {};
    const QJsonDocument targets = QJsonDocument::fromJson(targetsFile.readAll(), &error);
    const QJsonArray figures = targets.object().value(QStringLiteral("figures")).toArray();
    if (targets.isNull() || figures.isEmpty()) {
        std::fprintf(stderr, "bench_report: %s has no \"figures\" list (%s)\n",
                     qPrintable(arguments.at(1)), qPrintable(error.errorString()));
        return 2;
    }

    Results results(arguments.at(2));
    QString table = QStringLiteral("| figure | measured | target | wire/physical limit | met? |\n"
                                   "|---|---|---|---|---|\n");
    int counts[5] = {}; // by Verdict
    for (const QJsonValue &entry : figures) {
        const Row row = evaluate(entry.toObject(), results);
        ++counts[int(row.verdict)];
        table += QStringLiteral("| %1 | %2 | %3 | %4 | %5 |\n")
                     .arg(row.figure, row.measured, row.target, row.wire, verdictText(row.verdict));
    }
    const int measured =
        counts[int(Verdict::Met)] + counts[int(Verdict::NotMet)] + counts[int(Verdict::Missing)];
    table += QStringLiteral("\n%1 of %2 figures met, %3 not met, %4 missing; %5 measured "
                            "separately, not by run-all; %6 for reference.\n")
                 .arg(counts[int(Verdict::Met)])
                 .arg(measured)
                 .arg(counts[int(Verdict::NotMet)])
                 .arg(counts[int(Verdict::Missing)])
                 .arg(counts[int(Verdict::Elsewhere)])
                 .arg(counts[int(Verdict::Reference)]);
    std::printf("%s", table.toUtf8().constData());
    return counts[int(Verdict::Met)] == measured ? 0 : 1;
}
