// Replaying a recording (`rtcoord serve --replay FILE`): the page as it was at any moment of the run,
// chosen with a time slider or played forward, as Groot2 replays its logs.
'use strict';

const REPLAY_TICK = 100; // ms between steps while playing

/** Takes over the page with [recording]: its entries ({ kind, at, data }), the snapshot first. */
function startReplay(recording) {
  if (!recording.length || recording[0].kind !== 'snapshot') {
    connected(false, 'the recording does not start with a snapshot');
    return;
  }
  const start = recording[0].at;
  view.replay = { entries: recording, start, end: recording[recording.length - 1].at, applied: -1, playing: null, speed: 1 };
  const slider = document.getElementById('replay-at');
  slider.max = String(view.replay.end - start);
  slider.value = '0';
  slider.addEventListener('input', () => { stopPlaying(); seek(start + Number(slider.value)); });
  document.getElementById('replay-play').addEventListener('click', () => (view.replay.playing ? stopPlaying() : play()));
  document.getElementById('replay-speed').addEventListener('change', event => { view.replay.speed = Number(event.target.value); });
  document.getElementById('replay').hidden = false;
  // `?at=12.5` opens the recording 12.5 s after its start (`serve --replay FILE --at 12.5s`).
  const at = Number(new URLSearchParams(location.search).get('at'));
  seek(Number.isFinite(at) && at > 0 ? Math.min(view.replay.end, start + Math.round(at * 1000)) : start);
}

/**
 * The page as it was at [at] (the recording's clock): every entry up to then applied in order. Going
 * forward applies only what is new; going back starts again from the snapshot.
 */
function seek(at) {
  const replay = view.replay;
  let last = 0;
  while (last + 1 < replay.entries.length && replay.entries[last + 1].at <= at) last++;
  if (last < replay.applied) replay.applied = -1;
  for (let i = replay.applied + 1; i <= last; i++) apply(replay.entries[i].kind, replay.entries[i].data);
  replay.applied = last;
  replay.at = at;
  document.getElementById('replay-at').value = String(at - replay.start);
  document.getElementById('replay-time').textContent = time(new Date(at).toISOString()) + ' (' + ((at - replay.start) / 1000).toFixed(1) + ' s of ' +
    ((replay.end - replay.start) / 1000).toFixed(1) + ' s, ' + (last + 1) + '/' + replay.entries.length + ' entries)';
}

function play() {
  const replay = view.replay;
  if (replay.at >= replay.end) seek(replay.start);
  document.getElementById('replay-play').textContent = 'pause';
  replay.playing = setInterval(() => {
    seek(Math.min(replay.end, replay.at + REPLAY_TICK * replay.speed));
    if (replay.at >= replay.end) stopPlaying();
  }, REPLAY_TICK);
}

function stopPlaying() {
  clearInterval(view.replay.playing);
  view.replay.playing = null;
  document.getElementById('replay-play').textContent = 'play';
}
