// The search for the one servo: a broadcast PING per rate, then the one servo identified and read.
#include "motorfinder.h"

#include "linksession.h"
#include "sharedidcheck.h"

#include <QCoreApplication>

#include <algorithm>

namespace {

struct MotorFinderTr
{
    Q_DECLARE_TR_FUNCTIONS(MotorFinder)
};

} // namespace

namespace feetech {

namespace {

QString jointText(const QString &joint)
{
    return joint.isEmpty() ? MotorFinderTr::tr("this motor") : joint;
}

} // namespace

struct MotorFinder::Search
{
    // What a rate's broadcast PING brought back.
    struct Rate
    {
        qint32 baud = 0;
        QVector<quint8> ids; // of the clean replies
        bool collided = false; // more bytes came than the clean replies account for
    };

    QString model; // empty: any model with a register table
    QString joint;
    SearchDone done;
    QVector<qint32> rates;
    QVector<Rate> heard;
    MotorSearch result;
};

bool servoIsModel(const ServoInfo &servo, QStringView model)
{
    const auto wanted = ModelTable::builtIn().findByName(model);
    if (!wanted)
        return servo.model.name.compare(model, Qt::CaseInsensitive) == 0;
    return wanted->major == servo.modelMajor && wanted->minor == servo.modelMinor;
}

MotorFinder::MotorFinder(BusExchange &bus, std::function<bool()> stopRequested)
    : m_bus(bus)
    , m_stopRequested(std::move(stopRequested))
{ }

Exchange MotorFinder::identityRequest(quint8 id, bool quiet)
{
    Exchange ask;
    ask.request = feetech::read(id, kIdentityAddress, kIdentitySize);
    ask.replyId = id;
    ask.replyDataSize = kIdentitySize;
    ask.retryCount = 1;
    ask.silenceExpected = quiet;
    return ask;
}

void MotorFinder::find(const QString &model, const QString &joint, SearchDone done)
{
    auto search = std::make_shared<Search>();
    search->model = model;
    search->joint = joint;
    search->done = std::move(done);
    search->rates = baudRates();
    probeRate(search, 0);
}

void MotorFinder::probeRate(std::shared_ptr<Search> search, int index)
{
    if (m_stopRequested()) {
        search->result.stopped = true;
        endSearch(search, MotorSearch::Verdict::Failed,
                  MotorFinderTr::tr("Stopped; nothing was written."));
        return;
    }
    if (index == search->rates.size()) {
        decide(search);
        return;
    }
    const qint32 baud = search->rates.at(index);
    m_bus.setBaud(baud)([this, search, index, baud](bool ok, const QString &message) {
        if (!ok) {
            endSearch(search, MotorSearch::Verdict::Failed, message);
            return;
        }
        // Every servo at this rate answers a broadcast PING at once. None answers as the
        // broadcast ID, so each clean reply goes to otherFrame and the wait runs to its end;
        // bytes beyond the clean replies are replies that collided.
        auto ids = std::make_shared<QVector<quint8>>();
        Exchange ask;
        ask.request = feetech::ping(kBroadcastId);
        ask.replyId = kBroadcastId;
        ask.otherFrame = [ids](const Packet &packet) {
            if (packet.parameters.isEmpty())
                ids->append(packet.id);
        };
        ask.silenceExpected = true;
        ask.retryCount = 0;
        ask.replyTimeout = std::max(m_bus.timing().probeAllowance, m_bus.scanAllowance());
        m_bus.exchange(
            ask,
            [this, search, index, baud, ids](const seriallink::TransactionResult &result,
                                             const std::optional<Packet> &) {
                if (result.failure == seriallink::Failure::LinkDown
                    || result.failure == seriallink::Failure::Cancelled) {
                    endSearch(search, MotorSearch::Verdict::Failed, failureText(result));
                    return;
                }
                if (result.bytesHeard > 0)
                    search->heard.append(
                        {baud, *ids, result.bytesHeard > ids->size() * kMinimumPacketSize});
                probeRate(search, index + 1);
            });
    });
}

void MotorFinder::decide(std::shared_ptr<Search> search)
{
    MotorSearch &result = search->result;
    for (const Search::Rate &rate : std::as_const(search->heard)) {
        for (const quint8 id : rate.ids)
            result.answering.append(
                MotorFinderTr::tr("ID %1 at %2").arg(id).arg(baudText(rate.baud)));
        if (rate.collided)
            result.answering.append(
                MotorFinderTr::tr("several at %1 whose replies collide").arg(baudText(rate.baud)));
        // A collision takes at least two servos.
        result.count += int(rate.ids.size()) + (rate.collided ? 2 : 0);
        result.collided = result.collided || rate.collided;
    }
    if (search->heard.isEmpty()) {
        endSearch(
            search, MotorSearch::Verdict::NoServo,
            MotorFinderTr::tr("No servo answers at any rate: check the power and the cable, and "
                              "connect the next servo."));
        return;
    }
    const Search::Rate &first = search->heard.first();
    if (search->heard.size() == 1 && !first.collided && first.ids.size() == 1) {
        confirm(search, first.ids.first(), first.baud);
        return;
    }
    const bool oneId = search->heard.size() == 1 && !first.collided
        && std::all_of(first.ids.begin(), first.ids.end(),
                       [&first](quint8 id) { return id == first.ids.first(); });
    if (oneId) { // separate replies from one ID: servos with different return delays
        result.servo.id = first.ids.first();
        result.servo.baud = first.baud;
        endSearch(search, MotorSearch::Verdict::SharedId,
                  MotorFinderTr::tr("Two servos answer at ID %1; connect them one at a time.")
                      .arg(first.ids.first()));
        return;
    }
    const QString list = result.answering.join(QStringLiteral(", "));
    endSearch(
        search, MotorSearch::Verdict::SeveralServos,
        result.collided
            ? MotorFinderTr::tr("At least %1 servos answer (%2): connect one servo at a time.")
                  .arg(result.count)
                  .arg(list)
            : MotorFinderTr::tr("%1 servos answer (%2): connect one servo at a time.")
                  .arg(result.count)
                  .arg(list));
}

void MotorFinder::confirm(std::shared_ptr<Search> search, quint8 id, qint32 baud)
{
    search->result.servo.id = id;
    search->result.servo.baud = baud;
    search->result.count = 1;
    m_bus.setBaud(baud)([this, search, id, baud](bool ok, const QString &message) {
        if (!ok) {
            endSearch(search, MotorSearch::Verdict::Failed, message);
            return;
        }
        m_bus.exchange(
            identityRequest(id, false),
            [this, search, id, baud](const seriallink::TransactionResult &result,
                                     const std::optional<Packet> &reply) {
                if (result.failure == seriallink::Failure::LinkDown
                    || result.failure == seriallink::Failure::Cancelled) {
                    endSearch(search, MotorSearch::Verdict::Failed, failureText(result));
                    return;
                }
                const auto info =
                    reply ? servoInfoFromIdentity(id, baud, reply->parameters) : std::nullopt;
                if (info) {
                    search->result.servo = *info;
                    checkShared(search);
                } else if (result.bytesHeard > 0) { // their identities differ
                    search->result.count = 2;
                    endSearch(search, MotorSearch::Verdict::SharedId,
                              MotorFinderTr::tr("Two servos answer at ID %1; connect them one "
                                                "at a time.")
                                  .arg(id));
                } else {
                    // Replies of several IDs can collide into one that looks clean.
                    search->result.count = 2;
                    endSearch(search, MotorSearch::Verdict::SeveralServos,
                              MotorFinderTr::tr("A reply at %1 looked like servo %2, which then "
                                                "did not answer: probably several servos whose "
                                                "replies collide. Connect one servo at a time.")
                                  .arg(baudText(baud))
                                  .arg(id));
                }
            });
    });
}

void MotorFinder::checkShared(std::shared_ptr<Search> search)
{
    const ServoInfo &servo = search->result.servo;
    checkSharedId(
        m_bus, servo, false,
        [this, search](SharedIdVerdict verdict, const seriallink::TransactionResult &result) {
            const ServoInfo &servo = search->result.servo;
            switch (verdict) {
            case SharedIdVerdict::Failed:
                endSearch(search, MotorSearch::Verdict::Failed, failureText(result));
                return;
            case SharedIdVerdict::Shared:
                search->result.count = 2;
                endSearch(search, MotorSearch::Verdict::SharedId,
                          MotorFinderTr::tr("Two servos answer at ID %1; connect them one at a "
                                            "time.")
                              .arg(servo.id));
                return;
            case SharedIdVerdict::Silent:
                endSearch(search, MotorSearch::Verdict::NoServo,
                          MotorFinderTr::tr("%1 stopped answering: check the power and the "
                                            "cable, then look again.")
                              .arg(servoName(servo)));
                return;
            case SharedIdVerdict::One:
            case SharedIdVerdict::Unknown: // nothing known to read: its model decides
                judgeModel(search);
                return;
            }
        });
}

void MotorFinder::judgeModel(std::shared_ptr<Search> search)
{
    const ServoInfo &servo = search->result.servo;
    if (!servo.hasTable()) {
        endSearch(search, MotorSearch::Verdict::WrongModel,
                  MotorFinderTr::tr("Found %1, model %2 (model number %3), which ServoBench has no "
                                    "register table for; nothing was written.")
                      .arg(servoName(servo), servo.model.name)
                      .arg(servo.modelNumber()));
        return;
    }
    if (!search->model.isEmpty() && !servoIsModel(servo, search->model)) {
        endSearch(
            search, MotorSearch::Verdict::WrongModel,
            MotorFinderTr::tr("Found %1, model %2, but %3 needs model %4. Nothing was written: "
                              "connect a servo of model %4.")
                .arg(servoName(servo), servo.model.name, jointText(search->joint), search->model));
        return;
    }
    endSearch(search, MotorSearch::Verdict::OneServo,
              MotorFinderTr::tr("Found one servo: %1, model %2.")
                  .arg(servoName(servo), servo.model.name));
}

void MotorFinder::endSearch(std::shared_ptr<Search> search, MotorSearch::Verdict verdict,
                            const QString &message)
{
    search->result.verdict = verdict;
    search->result.message = message;
    const SearchDone done = std::move(search->done);
    search->done = nullptr;
    if (done)
        done(search->result);
}

} // namespace feetech
