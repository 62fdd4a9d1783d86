// Restarts the gyro when it fails, at most LIMIT times (the first argument, 3 by default); after that,
// or as soon as a reset fails (the fault persists), it stays in ERROR for a person to look at. A gyro
// already in ERROR at the start counts as a failure.
val limit = args.firstOrNull()?.toInt() ?: 3
var restarts = 0

on(component("gyro0.rtc")).state(ERROR, includeCurrent = true) {
    if (restarts >= limit) {
        log("gyro0 failed ${restarts + 1} times: leaving it in ERROR")
        return@state
    }
    restarts++
    log("gyro0 failed: restart $restarts of $limit")
    // A reset that fails leaves the gyro in ERROR, where no new failure will come to fire this rule again.
    if (!attempt { reset() }) {
        log("gyro0 cannot be reset: leaving it in ERROR")
        return@state
    }
    activate()
}
