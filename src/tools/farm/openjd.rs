//! Open Job Description jobs (specification 2023-09): the job template as
//! serde structs, written as JSON (which OpenJD reads, and which is YAML
//! too, so a `.yaml` name reads as well), and its job parameters' values.

use super::frames::{chunks, range_expression};
use super::{json, ColourConfig, Needs};
use crate::cli::command_line::{Flow, TaskCommand};
use crate::error::{Error, Result};
use crate::io::sequence::parse_frame_list;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::Path;

/// Most tasks an OpenJD task parameter may list.
const OPENJD_MAX_TASKS: usize = 1024;

/// Seconds an OpenJD task has between its cancel's SIGTERM and SIGKILL
/// (`NOTIFY_THEN_TERMINATE`): exrcomp abandons the frames in flight at once
/// and removes their temporaries, keeping every frame done; the period
/// bounds that, with room for a frame finishing if a later exrcomp does.
const CANCEL_NOTIFY_SECONDS: u32 = 120;

/// A job template, as the specification names its fields.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Template {
    specification_version: &'static str,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    extensions: Vec<&'static str>,
    name: String,
    description: String,
    parameter_definitions: Vec<Parameter>,
    steps: [Step; 1],
}

/// A job parameter.
#[derive(Serialize)]
#[serde(tag = "type", rename_all = "UPPERCASE")]
enum Parameter {
    #[serde(rename_all = "camelCase")]
    Path {
        name: String,
        object_type: &'static str,
        data_flow: DataFlow,
    },
    String {
        name: String,
        default: String,
    },
    #[serde(rename_all = "camelCase")]
    Int {
        name: String,
        default: usize,
        min_value: usize,
    },
}

/// Which way a PATH parameter's file goes.
#[derive(Serialize, Clone, Copy)]
#[serde(rename_all = "UPPERCASE")]
enum DataFlow {
    None,
    In,
    Out,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Step {
    name: &'static str,
    parameter_space: ParameterSpace,
    host_requirements: HostRequirements,
    step_environments: [Environment; 1],
    script: Script,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ParameterSpace {
    task_parameter_definitions: [TaskParameter; 1],
}

/// The `Frames` task parameter: a list of chunks, or the scheduler's.
#[derive(Serialize)]
#[serde(tag = "type")]
enum TaskParameter {
    #[serde(rename = "STRING")]
    Listed {
        name: &'static str,
        range: Vec<String>,
    },
    #[serde(rename = "CHUNK[INT]")]
    Chunked {
        name: &'static str,
        range: String,
        chunks: Chunks,
    },
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Chunks {
    default_task_count: String,
    range_constraint: RangeConstraint,
    #[serde(skip_serializing_if = "Option::is_none")]
    target_runtime_seconds: Option<u32>,
}

#[derive(Serialize)]
#[serde(rename_all = "UPPERCASE")]
enum RangeConstraint {
    Contiguous,
    Noncontiguous,
}

#[derive(Serialize)]
struct HostRequirements {
    amounts: [Amount; 2],
    attributes: [Attribute; 1],
}

#[derive(Serialize)]
struct Amount {
    name: &'static str,
    min: u64,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Attribute {
    name: &'static str,
    any_of: [&'static str; 1],
}

#[derive(Serialize)]
struct Environment {
    name: &'static str,
    description: &'static str,
    variables: BTreeMap<String, String>,
}

#[derive(Serialize)]
struct Script {
    actions: Actions,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Actions {
    on_run: Action,
}

#[derive(Serialize)]
struct Action {
    command: String,
    args: Vec<String>,
    cancelation: Cancelation,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Cancelation {
    mode: &'static str,
    notify_period_in_seconds: u32,
}

/// A job bundle's `parameter_values` file.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct BundleValues {
    parameter_values: Vec<NameValue>,
}

#[derive(Serialize)]
struct NameValue {
    name: String,
    value: String,
}

/// The job parameters a template gathers as its command is written, and
/// the values of its PATH parameters.
#[derive(Default)]
struct Parameters {
    definitions: Vec<Parameter>,
    values: BTreeMap<String, String>,
}

/// A job parameter's value in a format string.
fn reference(name: &str) -> String {
    format!("{{{{Param.{name}}}}}")
}

impl Parameters {
    /// `value` as the PATH parameter `name` (every path is a FILE: a
    /// sequence's pattern names files); its reference.
    fn path(&mut self, name: String, value: &str, data_flow: DataFlow) -> String {
        self.values.insert(name.clone(), value.into());
        let reference = reference(&name);
        self.definitions.push(Parameter::Path {
            name,
            object_type: "FILE",
            data_flow,
        });
        reference
    }

    /// `text` for a format string: itself, or when it holds `{{` (which
    /// would open an expression) a reference to a STRING parameter `name`
    /// whose default it is, a value OpenJD does not read as a format string.
    fn literal(&mut self, name: String, text: &str) -> String {
        if !text.contains("{{") {
            return text.to_string();
        }
        let reference = reference(&name);
        self.definitions.push(Parameter::String {
            name,
            default: text.to_string(),
        });
        reference
    }
}

/// A job's name within OpenJD's limits (jobtemplate-2023-09: 1 to 128
/// characters, no control character), else a usage error: refused here,
/// not by `openjd check` or the render manager once the template is out.
pub fn check_name(name: &str) -> Result<()> {
    let length = name.chars().count();
    if (1..=128).contains(&length) && !name.chars().any(char::is_control) {
        return Ok(());
    }
    Err(Error::usage(format!(
        "--name {name:?}: an OpenJD job's name is 1 to 128 characters, none a control character"
    )))
}

/// How an OpenJD job splits its frames into tasks.
pub enum Tasks {
    /// One STRING task parameter listing the chunks (any OpenJD scheduler).
    Listed(Vec<String>),
    /// A CHUNK[INT] task parameter over all the frames (the TASK_CHUNKING
    /// extension): the scheduler makes the chunks, adaptively towards a
    /// runtime if one is given.
    Chunked {
        frames: String,
        chunk: usize,
        contiguous: bool,
        target_seconds: Option<u32>,
    },
}

impl Tasks {
    pub fn new(
        frames: &str,
        chunk: usize,
        chunking: bool,
        target_seconds: Option<u32>,
    ) -> Result<Self> {
        if !chunking && target_seconds.is_none() {
            let chunks = chunks(frames, chunk)?;
            if chunks.len() > OPENJD_MAX_TASKS {
                return Err(Error::usage(format!(
                    "{} chunks: an OpenJD task parameter lists at most {OPENJD_MAX_TASKS}; \
                     give a larger --chunk, or --task-chunking for the scheduler to chunk",
                    chunks.len()
                )));
            }
            return Ok(Tasks::Listed(chunks));
        }
        if chunk == 0 {
            return Err(Error::usage("--chunk must be at least 1"));
        }
        let list = parse_frame_list(frames)?;
        Ok(Tasks::Chunked {
            contiguous: list.windows(2).all(|w| w[1] == w[0] + 1),
            frames: range_expression(&list),
            chunk,
            target_seconds,
        })
    }

    /// The template's extensions and its `Frames` task parameter; scheduler
    /// chunking adds the job parameters `Frames` and `ChunkSize`.
    fn openjd(&self, parameters: &mut Parameters) -> (Vec<&'static str>, TaskParameter) {
        let name = "Frames";
        match self {
            Tasks::Listed(chunks) => (
                Vec::new(),
                TaskParameter::Listed {
                    name,
                    range: chunks.clone(),
                },
            ),
            Tasks::Chunked {
                frames,
                chunk,
                contiguous,
                target_seconds,
            } => {
                parameters.definitions.extend([
                    Parameter::String {
                        name: name.into(),
                        default: frames.clone(),
                    },
                    Parameter::Int {
                        name: "ChunkSize".into(),
                        default: *chunk,
                        min_value: 1,
                    },
                ]);
                let chunks = Chunks {
                    default_task_count: reference("ChunkSize"),
                    range_constraint: match contiguous {
                        true => RangeConstraint::Contiguous,
                        false => RangeConstraint::Noncontiguous,
                    },
                    target_runtime_seconds: *target_seconds,
                };
                let range = reference(name);
                let task = TaskParameter::Chunked {
                    name,
                    range,
                    chunks,
                };
                (vec!["TASK_CHUNKING"], task)
            }
        }
    }
}

/// An Open Job Description job: its template and the values of its job
/// parameters.
pub struct OpenJdArgs {
    pub template: String,
    /// `{"NAME": "VALUE"}`, as `openjd run -p file://FILE` and render
    /// managers take job parameters.
    pub values: String,
    /// The same as a job bundle's `parameter_values.json` (`parameterValues`,
    /// a list of `name` and `value`), as `deadline bundle submit` reads it.
    pub bundle_values: String,
}

/// An Open Job Description job template: one step whose tasks are the frame
/// chunks. The executable and every file argument are PATH job parameters
/// (`Exrcomp`, `Input1`..., `Output`), which a render manager's path mapping
/// rewrites for the worker; OpenJD allows a PATH parameter no absolute
/// default, so their values go in `values`. An argument that holds `{{` goes
/// through a STRING job parameter, whose value is not a format string. With
/// scheduler chunking, `Frames` and `ChunkSize` are job parameters too, the
/// given values their defaults. The step asks for the task's threads and
/// memory bound (`hostRequirements`), and its environment carries the
/// submitter's `EXRCOMP_*` settings.
pub fn openjd_template(
    exrcomp: &Path,
    task: &TaskCommand,
    tasks: &Tasks,
    needs: &Needs,
    (name, description): (&str, String),
) -> OpenJdArgs {
    let mut parameters = Parameters::default();
    let command = parameters.path("Exrcomp".into(), &exrcomp.to_string_lossy(), DataFlow::None);
    let mut args = Vec::new();
    let mut inputs = 0;
    for (i, arg) in task.args.iter().enumerate() {
        let file = task.files.iter().find(|(at, _)| *at == i).map(|f| f.1);
        args.push(match file {
            Some(Flow::Out) => parameters.path("Output".into(), arg, DataFlow::Out),
            Some(Flow::In) => {
                inputs += 1;
                parameters.path(format!("Input{inputs}"), arg, DataFlow::In)
            }
            None => parameters.literal(format!("Arg{i}"), arg),
        });
    }
    args.extend(["--frames".into(), "{{Task.Param.Frames}}".into()]);
    let environment = environment(needs, &mut parameters);
    let (extensions, frames) = tasks.openjd(&mut parameters);
    let step = Step {
        name: "exrcomp",
        parameter_space: ParameterSpace {
            task_parameter_definitions: [frames],
        },
        host_requirements: HostRequirements {
            amounts: [
                Amount {
                    name: "amount.worker.vcpu",
                    min: needs.threads as u64,
                },
                Amount {
                    name: "amount.worker.memory",
                    min: needs.memory_mib(),
                },
            ],
            attributes: [Attribute {
                name: "attr.worker.os.family",
                any_of: ["linux"],
            }],
        },
        step_environments: [environment],
        script: Script {
            actions: Actions {
                on_run: Action {
                    command,
                    args,
                    cancelation: Cancelation {
                        mode: "NOTIFY_THEN_TERMINATE",
                        notify_period_in_seconds: CANCEL_NOTIFY_SECONDS,
                    },
                },
            },
        },
    };
    // The name is a format string too.
    let name = parameters.literal("JobName".into(), name);
    let template = Template {
        specification_version: "jobtemplate-2023-09",
        extensions,
        name,
        description,
        parameter_definitions: parameters.definitions,
        steps: [step],
    };
    let bundle_values = BundleValues {
        parameter_values: (parameters.values.iter())
            .map(|(name, value)| NameValue {
                name: name.clone(),
                value: value.clone(),
            })
            .collect(),
    };
    OpenJdArgs {
        template: json(&template),
        values: json(&parameters.values),
        bundle_values: json(&bundle_values),
    }
}

/// The step's environment: the colour config as the submitter resolved it
/// (a file a PATH parameter, mapped; a built-in one's name as it is) and
/// the `EXRCOMP_*` settings.
fn environment(needs: &Needs, parameters: &mut Parameters) -> Environment {
    let colour = match &needs.colour {
        ColourConfig::File(file) => parameters.path("ColourConfig".into(), file, DataFlow::In),
        ColourConfig::Name(name) => name.clone(),
    };
    let mut variables = BTreeMap::from([("OCIO".to_string(), colour)]);
    for (i, (name, value)) in needs.environment.iter().enumerate() {
        variables.insert(name.clone(), parameters.literal(format!("Env{i}"), value));
    }
    Environment {
        name: "ExrcompSettings",
        description: "The submitter's colour config and EXRCOMP_* settings",
        variables,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_path_parameters_and_braces_elsewhere_go_through_a_string() {
        let task = TaskCommand {
            args: [
                "over",
                "/s/a{{x}}.exr",
                "--layer",
                "l{{y}}",
                "-o",
                "/s/o.exr",
            ]
            .map(String::from)
            .to_vec(),
            files: vec![(1, Flow::In), (5, Flow::Out)],
        };
        let tasks = Tasks::new("1-4", 2, false, None).unwrap();
        let needs = Needs {
            threads: 2,
            memory: 1,
            environment: BTreeMap::new(),
            colour: ColourConfig::File("/s/c{{z}}.ocio".into()),
        };
        let job = openjd_template(
            Path::new("/bin/exrcomp"),
            &task,
            &tasks,
            &needs,
            ("n", "d".into()),
        );
        let template: serde_json::Value = serde_json::from_str(&job.template).unwrap();
        let step = &template["steps"][0];
        assert_eq!(
            step["script"]["actions"]["onRun"]["args"],
            serde_json::json!([
                "over",
                "{{Param.Input1}}",
                "--layer",
                "{{Param.Arg3}}",
                "-o",
                "{{Param.Output}}",
                "--frames",
                "{{Task.Param.Frames}}"
            ])
        );
        let parameters = template["parameterDefinitions"].as_array().unwrap();
        assert!(parameters
            .contains(&serde_json::json!({"name": "Arg3", "type": "STRING", "default": "l{{y}}"})));
        assert!(parameters.contains(&serde_json::json!({"name": "Output", "type": "PATH", "objectType": "FILE", "dataFlow": "OUT"})));
        let values: serde_json::Value = serde_json::from_str(&job.values).unwrap();
        assert_eq!(
            values,
            serde_json::json!({"Exrcomp": "/bin/exrcomp", "Input1": "/s/a{{x}}.exr", "Output": "/s/o.exr", "ColourConfig": "/s/c{{z}}.ocio"})
        );
        assert_eq!(
            step["stepEnvironments"][0]["variables"]["OCIO"],
            "{{Param.ColourConfig}}"
        );
        let bundle: serde_json::Value = serde_json::from_str(&job.bundle_values).unwrap();
        assert_eq!(
            bundle["parameterValues"][0],
            serde_json::json!({"name": "ColourConfig", "value": "/s/c{{z}}.ocio"})
        );
    }
}
