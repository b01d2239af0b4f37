//! The parts of the `shenlong` command that are worth testing from outside: the web
//! editor's server and the MCP server (the editing session they share is
//! [`shenlong::session`]).

pub mod mcp;
pub mod server;
pub mod terminal;
