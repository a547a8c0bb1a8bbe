// The fault soak as a benchmark program: 10,000 transactions per family (--transactions N; one
// family with --family) with 10 % of each fault, printing the counts as JSON; exit 1 when a value
// shown or a write's outcome was not what the simulator held.
#include "eventloops.h"
#include "faultsoak.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>

#include <cstdio>

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    soak::SoakOptions options;
    QString family; // both when empty
    const QStringList arguments = app.arguments().mid(1);
    for (int i = 0; i < arguments.size(); ++i) {
        bool ok = false;
        const auto next = [&] {
            return i + 1 < arguments.size() ? arguments.at(++i) : QString();
        };
        if (arguments.at(i) == QLatin1String("--transactions"))
            options.transactions = next().toInt(&ok);
        else if (arguments.at(i) == QLatin1String("--seed"))
            options.seed = next().toUInt(&ok);
        else if (arguments.at(i) == QLatin1String("--family")) {
            family = next();
            ok = family == QLatin1String("feetech") || family == QLatin1String("ptk");
        }
        if (!ok || options.transactions <= 0) {
            std::fprintf(
                stderr, "usage: bench_soak [--transactions N] [--seed N] [--family feetech|ptk]\n");
            return 2;
        }
    }
    QJsonObject figures {{QStringLiteral("transactions_per_family"), options.transactions},
                         {QStringLiteral("seed"), double(options.seed)},
                         {QStringLiteral("faults"),
                          QStringLiteral("drop, corrupt, truncate and noise of replies and lost "
                                         "requests, 10 % each")}};
    bool trustworthy = true;
    for (const auto &[name, run] : {std::pair {QStringLiteral("feetech"), &soak::soakFeetech},
                                    std::pair {QStringLiteral("ptk"), &soak::soakPtk}}) {
        if (!family.isEmpty() && family != name)
            continue;
        QElapsedTimer clock;
        clock.start();
        const soak::SoakCounts counts = run(options);
        QJsonObject result = counts.toJson();
        result.insert(QStringLiteral("seconds"), double(clock.elapsed()) / 1000.0);
        figures.insert(name, result);
        trustworthy = trustworthy && counts.trustworthy();
    }
    figures.insert(QStringLiteral("trustworthy"), trustworthy);
    std::printf("%s\n", QJsonDocument(figures).toJson(QJsonDocument::Indented).constData());
    return trustworthy ? 0 : 1;
}
