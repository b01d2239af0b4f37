//! A scripted OpenAI-compatible chat-completions server on 127.0.0.1 (a random port), for
//! tests: it answers requests in order from a script, records what it received, and stops
//! by itself after the script or a deadline.

#![allow(dead_code)]

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// One scripted answer.
#[derive(Clone, Debug)]
pub enum Reply {
    /// A 200 with this assistant message (and usage counts).
    Content(String),
    /// A 200 with this assistant message and no usage.
    ContentNoUsage(String),
    /// Any status with headers and a raw body.
    Raw(u16, Vec<(String, String)>, String),
    /// Accept, read the request, then say nothing for this long and close.
    Hang(Duration),
    /// A 200 whose body never ends (no length, `x` after `x` inside a reply's content),
    /// until the client hangs up or 30 s pass; the counter says how many bytes were sent.
    Endless(Arc<std::sync::atomic::AtomicUsize>),
}

/// A request as the server saw it.
#[derive(Clone, Debug)]
pub struct Captured {
    /// The request line's path.
    pub path: String,
    /// Header names lower-cased.
    pub headers: Vec<(String, String)>,
    /// The JSON body.
    pub body: serde_json::Value,
}

impl Captured {
    /// A header's value.
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }
}

/// A running mock server.
pub struct MockLlm {
    /// Base URL, up to and including `/v1`.
    pub url: String,
    /// What it received, in order.
    pub requests: Arc<Mutex<Vec<Captured>>>,
}

/// Computes a reply from the request's JSON body.
pub type Handler = Arc<dyn Fn(&serde_json::Value) -> Reply + Send + Sync>;

impl MockLlm {
    /// Starts a server that answers up to `max_requests` requests with `handler`, serving
    /// connections on `threads` threads.
    pub fn start_with(handler: Handler, max_requests: usize, threads: usize) -> Self {
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind 127.0.0.1");
        listener.set_nonblocking(true).expect("non-blocking accept");
        let url = format!("http://{}/v1", listener.local_addr().unwrap());
        let requests = Arc::new(Mutex::new(Vec::new()));
        let listener = Arc::new(listener);
        let served = Arc::new(std::sync::atomic::AtomicUsize::new(0));
        for _ in 0..threads.max(1) {
            let (listener, requests, handler, served) = (
                Arc::clone(&listener),
                Arc::clone(&requests),
                Arc::clone(&handler),
                Arc::clone(&served),
            );
            std::thread::spawn(move || {
                let deadline = Instant::now() + Duration::from_secs(300);
                while served.load(std::sync::atomic::Ordering::SeqCst) < max_requests
                    && Instant::now() < deadline
                {
                    match listener.accept() {
                        Ok((stream, _)) => {
                            served.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                            serve_with(stream, &requests, |body| handler(body));
                        }
                        Err(_) => std::thread::sleep(Duration::from_millis(1)),
                    }
                }
            });
        }
        Self { url, requests }
    }

    /// Starts a server that answers with `script`, one reply a request.
    pub fn start(script: Vec<Reply>) -> Self {
        let listener = TcpListener::bind("127.0.0.1:0").expect("bind 127.0.0.1");
        listener.set_nonblocking(true).expect("non-blocking accept");
        let url = format!("http://{}/v1", listener.local_addr().unwrap());
        let requests = Arc::new(Mutex::new(Vec::new()));
        let seen = Arc::clone(&requests);
        std::thread::spawn(move || {
            let deadline = Instant::now() + Duration::from_secs(60);
            let mut served = 0;
            while served < script.len() && Instant::now() < deadline {
                match listener.accept() {
                    Ok((stream, _)) => {
                        let reply = script[served].clone();
                        served += 1;
                        serve(stream, reply, &seen);
                    }
                    Err(_) => std::thread::sleep(Duration::from_millis(5)),
                }
            }
        });
        Self { url, requests }
    }

    /// How many requests arrived.
    pub fn count(&self) -> usize {
        self.requests.lock().unwrap().len()
    }

    /// The requests received.
    pub fn captured(&self) -> Vec<Captured> {
        self.requests.lock().unwrap().clone()
    }
}

fn serve(stream: TcpStream, reply: Reply, seen: &Arc<Mutex<Vec<Captured>>>) {
    serve_with(stream, seen, move |_| reply.clone());
}

fn serve_with(
    stream: TcpStream,
    seen: &Arc<Mutex<Vec<Captured>>>,
    reply: impl Fn(&serde_json::Value) -> Reply,
) {
    stream.set_nonblocking(false).ok();
    stream.set_read_timeout(Some(Duration::from_secs(10))).ok();
    let mut reader = BufReader::new(stream.try_clone().expect("clone stream"));
    let mut line = String::new();
    if reader.read_line(&mut line).is_err() {
        return;
    }
    let path = line.split_whitespace().nth(1).unwrap_or("").to_string();
    let mut headers = Vec::new();
    let mut length = 0usize;
    loop {
        let mut h = String::new();
        if reader.read_line(&mut h).is_err() || h == "\r\n" || h.is_empty() {
            break;
        }
        if let Some((k, v)) = h.trim_end().split_once(':') {
            let (k, v) = (k.trim().to_lowercase(), v.trim().to_string());
            if k == "content-length" {
                length = v.parse().unwrap_or(0);
            }
            headers.push((k, v));
        }
    }
    let mut body = vec![0; length];
    if reader.read_exact(&mut body).is_err() {
        return;
    }
    let body: serde_json::Value = serde_json::from_slice(&body).unwrap_or(serde_json::Value::Null);
    let reply = reply(&body);
    seen.lock().unwrap().push(Captured {
        path,
        headers,
        body,
    });
    let mut stream = stream;
    let (status, extra, text) = match reply {
        Reply::Hang(d) => {
            std::thread::sleep(d);
            return;
        }
        Reply::Endless(sent) => {
            let head = "HTTP/1.1 200 Mock\r\nContent-Type: application/json\r\nConnection: close\r\n\r\n{\"choices\": [{\"message\": {\"role\": \"assistant\", \"content\": \"";
            let chunk = vec![b'x'; 64 * 1024];
            let until = Instant::now() + Duration::from_secs(30);
            let mut ok = stream.write_all(head.as_bytes()).is_ok();
            while ok && Instant::now() < until {
                ok = stream.write_all(&chunk).is_ok();
                if ok {
                    sent.fetch_add(chunk.len(), std::sync::atomic::Ordering::SeqCst);
                }
            }
            return;
        }
        Reply::Content(content) => (200, vec![], serde_json::json!({
            "id": "mock", "object": "chat.completion",
            "choices": [{"index": 0, "message": {"role": "assistant", "content": content}, "finish_reason": "stop"}],
            "usage": {"prompt_tokens": 321, "completion_tokens": 45, "total_tokens": 366}
        }).to_string()),
        Reply::ContentNoUsage(content) => (200, vec![], serde_json::json!({
            "choices": [{"index": 0, "message": {"role": "assistant", "content": content}}]
        }).to_string()),
        Reply::Raw(status, headers, body) => (status, headers, body),
    };
    let mut response = format!("HTTP/1.1 {status} Mock\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n", text.len());
    for (k, v) in extra {
        response.push_str(&format!("{k}: {v}\r\n"));
    }
    response.push_str("\r\n");
    response.push_str(&text);
    let _ = stream.write_all(response.as_bytes());
    let _ = stream.flush();
}
