// Restarts the gyro when it fails, at most LIMIT times (the first argument, 3 by default); after that
// it stays in ERROR for a person to look at. A gyro already in ERROR at the start counts as a failure.
val limit = args.firstOrNull()?.toInt() ?: 3
var restarts = 0

on(component("gyro0.rtc")).state(ERROR, includeCurrent = true) {
    if (restarts < limit) {
        restarts++
        log("gyro0 failed: restart $restarts of $limit")
        reset()
        activate()
    } else {
        log("gyro0 failed ${restarts + 1} times: leaving it in ERROR")
    }
}
