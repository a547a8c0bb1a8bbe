// Every result a BusClient's replies report, as one signal a QSignalSpy can watch.
#pragma once

#include "busclient.h"

#include <QObject>

// The outcome of each operation submitted to `client` from now on, whoever submitted it: the
// steps of an apply chain (final unset), then each final result, in the order they come.
class OperationLog : public QObject
{
    Q_OBJECT

public:
    explicit OperationLog(feetech::BusClient *client, QObject *parent = nullptr);

signals:
    void finished(const feetech::OperationResult &result);
};
