// bench_report TARGETS RESULTS: the machine, then one Markdown table of the benchmark figures in
// RESULTS (as bench/run-all saves them: <program>.<run>.json for runs 1, 2, 3..., and
// machine.json) against the targets in TARGETS (bench/targets.json). Each figure is the median of
// its runs, judged against its target (every run, for a figure marked every_run), with every
// run's value beside it. Exit 0 when every measured figure meets its target, 1 when one does not
// or is missing (a GUI figure measured on another platform than its target names counts as
// missing), 2 when the targets file cannot be read.
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QVariant>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace {

struct Lookup
{
    std::optional<double> value;
    QString problem; // why there is no value
};

// The element of `array` whose `key` reads `text`; a number reads as its shortest text, so
// rate_hz=100 finds 100.0.
QJsonValue elementWith(const QJsonArray &array, const QString &key, const QString &text)
{
    for (const QJsonValue &element : array) {
        if (element.toObject().value(key).toVariant().toString() == text)
            return element;
    }
    return QJsonValue(QJsonValue::Undefined);
}

// The value at `path` from `root`: keys, indexes into arrays, and key=text for the element of an
// array whose key reads text (runs.rate_hz=max.samples_per_s), joined by dots.
QJsonValue follow(QJsonValue value, const QString &path)
{
    for (const QString &step : path.split(u'.')) {
        if (!value.isArray()) {
            value = value.toObject().value(step);
            continue;
        }
        const QJsonArray array = value.toArray();
        const qsizetype equals = step.indexOf(u'=');
        bool isIndex = false;
        const int index = step.toInt(&isIndex);
        value = equals > 0 ? elementWith(array, step.left(equals), step.mid(equals + 1))
            : isIndex      ? array.at(index)
                           : QJsonValue(QJsonValue::Undefined);
    }
    return value;
}

class Results
{
public:
    explicit Results(const QString &folder)
        : m_folder(folder)
    {
        QFile file(m_folder.filePath(QStringLiteral("machine.json")));
        if (file.open(QIODevice::ReadOnly)) {
            m_machine = QJsonDocument::fromJson(file.readAll()).object();
            m_hasMachine = !m_machine.isEmpty();
        }
        m_runs = m_machine.value(QStringLiteral("runs")).toInt();
        if (m_runs > 0)
            return;
        // No machine.json: as many runs as the highest run number of any results file.
        static const QRegularExpression runFile(QStringLiteral("\\.([0-9]+)\\.json$"));
        for (const QString &name : m_folder.entryList({QStringLiteral("*.json")}, QDir::Files)) {
            const QRegularExpressionMatch match = runFile.match(name);
            if (match.hasMatch())
                m_runs = std::max(m_runs, match.captured(1).toInt());
        }
        m_runs = std::max(m_runs, 1);
    }

    int runs() const { return m_runs; }
    bool hasMachine() const { return m_hasMachine; }
    const QJsonObject &machine() const { return m_machine; }

    // The number at `path` in <program>.<run>.json.
    Lookup number(const QString &program, int run, const QString &path)
    {
        const QString name = fileName(program, run);
        const QJsonDocument &document = load(name);
        // A program that failed leaves its file empty or cut short.
        if (document.isNull() && m_folder.exists(name))
            return {std::nullopt, QStringLiteral("%1 holds no JSON").arg(name)};
        if (document.isNull())
            return {std::nullopt, QStringLiteral("no %1").arg(name)};
        const QJsonValue value = follow(document.isArray() ? QJsonValue(document.array())
                                                           : QJsonValue(document.object()),
                                        path);
        if (!value.isDouble())
            return {std::nullopt, QStringLiteral("no %1 in %2").arg(path, name)};
        return {value.toDouble(), {}};
    }

    // The text at top-level `key` of <program>.<run>.json; empty when there is none.
    QString text(const QString &program, int run, const QString &key)
    {
        return load(fileName(program, run)).object().value(key).toString();
    }

private:
    static QString fileName(const QString &program, int run)
    {
        return QStringLiteral("%1.%2.json").arg(program).arg(run);
    }

    const QJsonDocument &load(const QString &name)
    {
        if (!m_documents.contains(name)) {
            QFile file(m_folder.filePath(name));
            QJsonDocument document;
            if (file.open(QIODevice::ReadOnly))
                document = QJsonDocument::fromJson(file.readAll());
            m_documents.insert(name, document);
        }
        return m_documents[name];
    }

    QDir m_folder;
    QJsonObject m_machine;
    bool m_hasMachine = false;
    int m_runs = 1;
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

// One figure's value in each run, and for each run without one, why.
struct Series
{
    QVector<std::optional<double>> values; // by run, the first run first
    QStringList reasons; // by run: why it has no value; empty when it has one

    void add(double value)
    {
        values.append(value);
        reasons.append(QString());
    }
    void addMissing(const QString &reason)
    {
        values.append(std::nullopt);
        reasons.append(reason);
    }

    int count() const
    {
        return int(std::count_if(values.begin(), values.end(),
                                 [](const std::optional<double> &v) { return v.has_value(); }));
    }

    // "run 2: no p.2.json; run 3: ..."
    QString problems() const
    {
        QStringList texts;
        for (int run = 1; run <= reasons.size(); ++run) {
            if (!reasons.at(run - 1).isEmpty())
                texts.append(QStringLiteral("run %1: %2").arg(run).arg(reasons.at(run - 1)));
        }
        return texts.join(QStringLiteral("; "));
    }

    // The middle value; with an even count, the mean of the two middle ones.
    std::optional<double> median() const
    {
        QVector<double> present;
        for (const std::optional<double> &value : values) {
            if (value)
                present.append(*value);
        }
        if (present.isEmpty())
            return std::nullopt;
        std::sort(present.begin(), present.end());
        const qsizetype middle = present.size() / 2;
        return present.size() % 2 ? present.at(middle)
                                  : (present.at(middle - 1) + present.at(middle)) / 2;
    }

    // Whether the runs that have a value all have the same one.
    bool allEqual() const
    {
        const std::optional<double> first = median();
        return std::all_of(values.begin(), values.end(),
                           [&first](const std::optional<double> &v) { return !v || v == first; });
    }

    // Every run's value in run order, "—" for a run without one: " (1.15, —, 1.18)"; nothing
    // when there is only one run.
    QString runs() const
    {
        if (values.size() < 2)
            return {};
        QStringList texts;
        for (const std::optional<double> &value : values)
            texts.append(value ? number(*value) : QStringLiteral("—"));
        return QStringLiteral(" (") + texts.join(QStringLiteral(", ")) + u')';
    }
};

enum class Verdict { Met, NotMet, Missing, Elsewhere, Reference };

struct Row
{
    QString figure;
    QString measured;
    QString target;
    QString wire;
    Verdict verdict = Verdict::Missing;
    bool fewerRuns = false; // judged on fewer runs than the results hold
};

// The number at `path` of `program` in every run.
Series collect(Results &results, const QString &program, const QString &path)
{
    Series series;
    for (int run = 1; run <= results.runs(); ++run) {
        const Lookup lookup = results.number(program, run, path);
        if (lookup.value)
            series.add(*lookup.value);
        else
            series.addMissing(lookup.problem);
    }
    return series;
}

// The runs of `shown` measured on `platform` (all of them when it is empty), the others missing;
// the platforms they were measured on go to `otherPlatforms`. A GUI figure counts only from the
// display its target names: Qt's offscreen platform draws nothing, so its CPU and start-up times
// are not what a user sees.
Series onPlatform(const Series &shown, const QString &platform, const QString &program,
                  Results &results, QStringList *otherPlatforms)
{
    Series counted;
    for (int run = 1; run <= shown.values.size(); ++run) {
        const std::optional<double> value = shown.values.at(run - 1);
        if (!value) {
            counted.addMissing(shown.reasons.at(run - 1));
            continue;
        }
        const QString used =
            platform.isEmpty() ? platform : results.text(program, run, QStringLiteral("platform"));
        if (used == platform) {
            counted.add(*value);
            continue;
        }
        const QString named = used.isEmpty() ? QStringLiteral("an unnamed platform") : used;
        if (!otherPlatforms->contains(named))
            otherPlatforms->append(named);
        counted.addMissing(QStringLiteral("measured on %1, not on %2").arg(named, platform));
    }
    return counted;
}

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
    // A count of failures (samples dropped) must hold in every run: a median would hide one bad
    // run among good ones.
    const bool everyRun = entry.value(QStringLiteral("every_run")).toBool();
    row.target = reference ? QStringLiteral("none (for reference)")
                           : sign + u' '
            + (relative ? QString::number(target) + QStringLiteral(" × wire")
                        : withUnit(QString::number(target), unit))
            + (everyRun ? QStringLiteral(" in every run") : QString());

    const QString program = entry.value(QStringLiteral("program")).toString();
    const QJsonObject wire = entry.value(QStringLiteral("wire")).toObject();
    Series wireSeries;
    if (wire.contains(QStringLiteral("value"))) {
        wireSeries = collect(results, wire.value(QStringLiteral("program")).toString(program),
                             wire.value(QStringLiteral("value")).toString());
        const QString wireUnit = wire.value(QStringLiteral("unit")).toString(unit);
        const std::optional<double> median = wireSeries.median();
        // A wire limit is mostly arithmetic, the same in every run: its runs only when they differ
        // (a run without one is said in the measured column).
        row.wire = !median          ? QStringLiteral("missing (%1)").arg(wireSeries.problems())
            : wireSeries.allEqual() ? withUnit(number(*median), wireUnit)
                                    : withUnit(number(*median), wireUnit) + wireSeries.runs();
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

    const QString path = entry.value(QStringLiteral("value")).toString();
    const QString platform = entry.value(QStringLiteral("platform")).toString();
    const Series shown = collect(results, program, path);
    QStringList otherPlatforms;
    const Series counted = onPlatform(shown, platform, program, results, &otherPlatforms);
    if (counted.count() == 0) {
        row.measured = shown.count() == 0
            ? QStringLiteral("missing (%1)").arg(shown.problems())
            : QStringLiteral("%1%2, not counted: measured on %3, not on %4")
                  .arg(withUnit(number(*shown.median()), unit), shown.runs(),
                       otherPlatforms.join(QStringLiteral(" and ")), platform);
        return row;
    }

    // Relative to the wire: each run's figure over that run's wire limit, and the median of those.
    Series judged = counted;
    if (relative) {
        judged = Series();
        for (int run = 1; run <= results.runs(); ++run) {
            const std::optional<double> value = counted.values.at(run - 1);
            const std::optional<double> limit = wireSeries.values.value(run - 1);
            if (!value)
                judged.addMissing(counted.reasons.at(run - 1));
            else if (!limit || *limit <= 0)
                judged.addMissing(QStringLiteral("no wire figure"));
            else
                judged.add(*value / *limit);
        }
        if (judged.count() == 0) {
            row.measured = withUnit(number(*counted.median()), unit) + counted.runs()
                + QStringLiteral(" (no wire figure to compare with)");
            return row;
        }
        row.measured = QStringLiteral("%1 × wire%2; median %3")
                           .arg(number(*judged.median()), judged.runs(),
                                withUnit(number(*counted.median()), unit));
    } else {
        row.measured = withUnit(number(*counted.median()), unit) + counted.runs();
    }
    if (judged.count() < judged.values.size()) {
        row.fewerRuns = true;
        row.measured += QStringLiteral("; %1 of %2 runs, %3")
                            .arg(judged.count())
                            .arg(judged.values.size())
                            .arg(judged.problems());
    }
    if (reference) {
        row.verdict = Verdict::Reference;
        return row;
    }
    const auto meets = [&compare, target](double value) {
        return compare == QLatin1String(">=") ? value >= target : value <= target;
    };
    if (!everyRun) {
        row.verdict = meets(*judged.median()) ? Verdict::Met : Verdict::NotMet;
        return row;
    }
    QStringList failing;
    for (int run = 1; run <= judged.values.size(); ++run) {
        const std::optional<double> value = judged.values.at(run - 1);
        if (value && !meets(*value))
            failing.append(QString::number(run));
    }
    row.verdict = failing.isEmpty() ? Verdict::Met : Verdict::NotMet;
    if (!failing.isEmpty())
        row.measured +=
            QStringLiteral("; not met in run %1").arg(failing.join(QStringLiteral(", ")));
    return row;
}

QString verdictText(const Row &row, int runs)
{
    const QString fewer =
        row.fewerRuns ? QStringLiteral(" (fewer than %1 runs)").arg(runs) : QString();
    switch (row.verdict) {
    case Verdict::Met:
        return QStringLiteral("yes") + fewer;
    case Verdict::NotMet:
        return QStringLiteral("**NO**") + fewer;
    case Verdict::Missing:
        return QStringLiteral("**missing**");
    case Verdict::Elsewhere:
    case Verdict::Reference:
        break;
    }
    return QStringLiteral("—");
}

// The machine the figures come from, as bench/run-all recorded it in machine.json.
QString machineText(const Results &results)
{
    if (!results.hasMachine())
        return QStringLiteral("Machine: not recorded (no machine.json in the results folder).\n");
    const QJsonObject &machine = results.machine();
    const auto field = [&machine](const char *key) {
        const QJsonValue value = machine.value(QLatin1String(key));
        const QString text = value.isDouble() ? number(value.toDouble()) : value.toString();
        return text.isEmpty() ? QStringLiteral("unknown") : text;
    };
    return QStringLiteral("Machine: %1, %2 cores, %3 memory; %4; Qt %5; GUI platform %6.\n"
                          "Run on %7, load average at the start %8. Each figure is the median of "
                          "%9 runs, their values in run order in brackets.\n")
        .arg(field("cpu"), field("cores"), field("memory"), field("os"), field("qt"),
             field("gui_platform"), field("date"), field("load_average"),
             QString::number(results.runs()));
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
    QString report = machineText(results);
    report += QStringLiteral("\n| figure | measured | target | wire/physical limit | met? |\n"
                             "|---|---|---|---|---|\n");
    int counts[5] = {}; // by Verdict
    int fewerRuns = 0;
    for (const QJsonValue &entry : figures) {
        const Row row = evaluate(entry.toObject(), results);
        ++counts[int(row.verdict)];
        fewerRuns += row.fewerRuns ? 1 : 0;
        report += QStringLiteral("| %1 | %2 | %3 | %4 | %5 |\n")
                      .arg(row.figure, row.measured, row.target, row.wire,
                           verdictText(row, results.runs()));
    }
    const int measured =
        counts[int(Verdict::Met)] + counts[int(Verdict::NotMet)] + counts[int(Verdict::Missing)];
    report += QStringLiteral("\n%1 of %2 figures met, %3 not met, %4 missing; %5 measured "
                             "separately, not by run-all; %6 for reference; %7 from fewer than "
                             "%8 runs.\n")
                  .arg(counts[int(Verdict::Met)])
                  .arg(measured)
                  .arg(counts[int(Verdict::NotMet)])
                  .arg(counts[int(Verdict::Missing)])
                  .arg(counts[int(Verdict::Elsewhere)])
                  .arg(counts[int(Verdict::Reference)])
                  .arg(fewerRuns)
                  .arg(results.runs());
    std::printf("%s", report.toUtf8().constData());
    return counts[int(Verdict::Met)] == measured ? 0 : 1;
}
